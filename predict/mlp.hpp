#pragma once
// A small fully connected network (multi-layer perceptron) in Eigen, float: the predictor's
// encoders and heads are all of this kind. Batches are matrices with one sample per column.
#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace haptex::predict {

enum class Activation { linear, relu, softplus };
std::string activation_name(Activation activation);
Activation parse_activation(const std::string& name);  // throws haptex::Error for an unknown name

struct DenseLayer {
  Eigen::MatrixXf weight;  // outputs x inputs
  Eigen::VectorXf bias;    // outputs
  Activation activation = Activation::linear;
};

struct Mlp {
  std::vector<DenseLayer> layers;
  Eigen::Index inputs() const { return layers.front().weight.cols(); }
  Eigen::Index outputs() const { return layers.back().weight.rows(); }
  std::size_t parameters() const;
};

// sizes = {inputs, hidden..., outputs}; hidden layers use `hidden`, the last `output`. He-normal
// weights from the seed, zero biases.
Mlp make_mlp(std::span<const int> sizes, Activation hidden, Activation output, std::uint64_t seed);

// In place on pre-activations.
void activate(Activation activation, Eigen::Ref<Eigen::MatrixXf> values);

// Every layer's output for a batch, kept for back-propagation: out[0] is the input.
struct MlpTrace {
  std::vector<Eigen::MatrixXf> out;
};
void forward(const Mlp& net, const Eigen::MatrixXf& input, MlpTrace& trace);

struct MlpGradient {
  std::vector<Eigen::MatrixXf> weight;
  std::vector<Eigen::VectorXf> bias;
  explicit MlpGradient(const Mlp& net);
  void zero();
  MlpGradient& operator+=(const MlpGradient& other);
};

// d_output: dLoss/d(network output) for the batch of `trace` (consumed). Adds the parameters'
// gradients to `gradient`; fills d_input with dLoss/d(input) when it is not null.
void backward(const Mlp& net, const MlpTrace& trace, Eigen::MatrixXf d_output, MlpGradient& gradient,
              Eigen::MatrixXf* d_input = nullptr);

}  // namespace haptex::predict
