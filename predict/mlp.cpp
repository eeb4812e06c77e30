#include "predict/mlp.hpp"

#include <cmath>
#include <random>

#include "core/error.hpp"

namespace haptex::predict {

std::string activation_name(Activation activation) {
  switch (activation) {
    case Activation::relu: return "relu";
    case Activation::softplus: return "softplus";
    default: return "linear";
  }
}

Activation parse_activation(const std::string& name) {
  for (Activation a : {Activation::linear, Activation::relu, Activation::softplus})
    if (activation_name(a) == name) return a;
  throw failure("unknown activation '" + name + "' (linear, relu or softplus)");
}

std::size_t Mlp::parameters() const {
  std::size_t n = 0;
  for (const DenseLayer& l : layers) n += std::size_t(l.weight.size() + l.bias.size());
  return n;
}

Mlp make_mlp(std::span<const int> sizes, Activation hidden, Activation output, std::uint64_t seed) {
  if (sizes.size() < 2) throw failure("make_mlp: a network needs at least inputs and outputs");
  std::mt19937_64 rng(seed);
  std::normal_distribution<float> normal(0.0f, 1.0f);
  Mlp net;
  for (std::size_t i = 0; i + 1 < sizes.size(); ++i) {
    DenseLayer layer;
    // He initialisation keeps the ReLU layers' activations at a steady scale.
    const float scale = std::sqrt(2.0f / float(sizes[i]));
    layer.weight = Eigen::MatrixXf::NullaryExpr(sizes[i + 1], sizes[i], [&] { return scale * normal(rng); });
    layer.bias = Eigen::VectorXf::Zero(sizes[i + 1]);
    layer.activation = i + 2 == sizes.size() ? output : hidden;
    net.layers.push_back(std::move(layer));
  }
  return net;
}

void activate(Activation activation, Eigen::Ref<Eigen::MatrixXf> values) {
  if (activation == Activation::relu) {
    values = values.cwiseMax(0.0f);
  } else if (activation == Activation::softplus) {
    // log(1 + e^z) without overflow: max(z, 0) + log1p(e^-|z|), in Eigen's vectorised exp and log1p.
    values.array() = values.array().max(0.0f) + (-values.array().abs()).exp().log1p();
  }
}

void forward(const Mlp& net, const Eigen::MatrixXf& input, MlpTrace& trace) {
  trace.out.resize(net.layers.size() + 1);
  trace.out[0] = input;
  for (std::size_t i = 0; i < net.layers.size(); ++i) {
    const DenseLayer& l = net.layers[i];
    trace.out[i + 1].noalias() = l.weight * trace.out[i];
    trace.out[i + 1].colwise() += l.bias;
    activate(l.activation, trace.out[i + 1]);
  }
}

MlpGradient::MlpGradient(const Mlp& net) {
  for (const DenseLayer& l : net.layers) {
    weight.push_back(Eigen::MatrixXf::Zero(l.weight.rows(), l.weight.cols()));
    bias.push_back(Eigen::VectorXf::Zero(l.bias.size()));
  }
}

void MlpGradient::zero() {
  for (auto& w : weight) w.setZero();
  for (auto& b : bias) b.setZero();
}

MlpGradient& MlpGradient::operator+=(const MlpGradient& other) {
  for (std::size_t i = 0; i < weight.size(); ++i) {
    weight[i] += other.weight[i];
    bias[i] += other.bias[i];
  }
  return *this;
}

namespace {

// The activation's derivative from its output alone: relu 1 where the output is positive;
// softplus sigmoid(z) = 1 - e^-a for a = softplus(z).
void times_activation_derivative(Activation activation, const Eigen::MatrixXf& output, Eigen::MatrixXf& delta) {
  if (activation == Activation::relu)
    delta = delta.cwiseProduct((output.array() > 0.0f).cast<float>().matrix());
  else if (activation == Activation::softplus)
    delta = delta.cwiseProduct((1.0f - (-output.array()).exp()).matrix());
}

}  // namespace

void backward(const Mlp& net, const MlpTrace& trace, Eigen::MatrixXf delta, MlpGradient& gradient, Eigen::MatrixXf* d_input) {
  for (std::size_t i = net.layers.size(); i-- > 0;) {
    const DenseLayer& l = net.layers[i];
    times_activation_derivative(l.activation, trace.out[i + 1], delta);
    gradient.weight[i].noalias() += delta * trace.out[i].transpose();
    gradient.bias[i] += delta.rowwise().sum();
    if (i > 0 || d_input) {
      Eigen::MatrixXf previous = l.weight.transpose() * delta;
      delta = std::move(previous);
    }
  }
  if (d_input) *d_input = std::move(delta);
}

}  // namespace haptex::predict
