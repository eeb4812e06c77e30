#include "predict/mlp.hpp"

#include <gtest/gtest.h>

#include "predict/adam.hpp"

namespace haptex::predict {
namespace {

// Loss = sum of squares of the output, whose gradient with respect to the output is 2 * output.
double loss(const Mlp& net, const Eigen::MatrixXf& x) {
  MlpTrace t;
  forward(net, x, t);
  return double(t.out.back().squaredNorm());
}

// The pattern of active ReLUs: a finite difference that changes it straddles a kink and says nothing
// about the gradient.
std::vector<bool> active(const Mlp& net, const Eigen::MatrixXf& x) {
  MlpTrace t;
  forward(net, x, t);
  std::vector<bool> out;
  for (std::size_t i = 1; i + 1 < t.out.size(); ++i)
    for (Eigen::Index j = 0; j < t.out[i].size(); ++j) out.push_back(t.out[i].data()[j] > 0);
  return out;
}

class MlpGradientTest : public ::testing::TestWithParam<Activation> {};

// Back-propagation against central finite differences, in double-checked float: every weight and
// bias of a small net, every activation kind as the output layer.
TEST_P(MlpGradientTest, MatchesFiniteDifferences) {
  const int sizes[] = {5, 7, 6, 3};
  Mlp net = make_mlp(sizes, Activation::relu, GetParam(), 11);
  for (auto& l : net.layers) l.bias.setConstant(0.05f);  // keeps ReLUs away from their kink
  std::srand(5);
  const Eigen::MatrixXf x = Eigen::MatrixXf::Random(5, 4);
  const std::vector<bool> pattern = active(net, x);
  std::size_t checked = 0;
  MlpTrace t;
  forward(net, x, t);
  MlpGradient g(net);
  Eigen::MatrixXf d_input;
  backward(net, t, 2.0f * t.out.back(), g, &d_input);
  const float h = 1e-2f;
  double worst = 0;
  for (std::size_t i = 0; i < net.layers.size(); ++i)
    for (Eigen::Index j = 0; j < net.layers[i].weight.size(); ++j) {
      float& w = net.layers[i].weight.data()[j];
      const float saved = w;
      w = saved + h;
      const double up = loss(net, x);
      bool kink = active(net, x) != pattern;
      w = saved - h;
      const double down = loss(net, x);
      kink = kink || active(net, x) != pattern;
      w = saved;
      if (kink) continue;
      ++checked;
      const double numeric = (up - down) / (2 * h), analytic = g.weight[i].data()[j];
      const double error = std::abs(numeric - analytic) / (1e-2 + std::abs(numeric));
      if (error > 2e-2) ADD_FAILURE() << "layer " << i << " weight " << j << ": numeric " << numeric << " analytic " << analytic;
      worst = std::max(worst, error);
    }
  EXPECT_LT(worst, 2e-2) << activation_name(GetParam());
  EXPECT_GT(checked, 80u);  // of 98 weights
  // The input gradient too (used to reach the action encoder through the predictor).
  Eigen::MatrixXf xp = x;
  xp(2, 1) += h;
  const double up = loss(net, xp);
  xp(2, 1) -= 2 * h;
  const double numeric = (up - loss(net, xp)) / (2 * h);
  EXPECT_NEAR(d_input(2, 1), numeric, 2e-2 * (1e-2 + std::abs(numeric)));
}

INSTANTIATE_TEST_SUITE_P(OutputActivations, MlpGradientTest,
                         ::testing::Values(Activation::linear, Activation::relu, Activation::softplus));

TEST(Mlp, SoftplusIsFiniteAndNonNegativeForHugeInputs) {
  Eigen::MatrixXf z(1, 4);
  z << -1e30f, -50.0f, 50.0f, 1e30f;
  activate(Activation::softplus, z);
  for (Eigen::Index i = 0; i < z.size(); ++i) {
    EXPECT_TRUE(std::isfinite(z(i)));
    EXPECT_GE(z(i), 0.0f);
  }
  EXPECT_FLOAT_EQ(z(2), 50.0f);
}

TEST(Adam, FitsALinearMap) {
  const int sizes[] = {3, 2};
  Mlp net = make_mlp(sizes, Activation::relu, Activation::linear, 3);
  Eigen::MatrixXf a(2, 3);
  a << 1, -2, 0.5, 0, 3, -1;
  Adam adam(net, {0.05f});
  const Eigen::MatrixXf x = Eigen::MatrixXf::Random(3, 64), y = a * x;
  for (int step = 0; step < 500; ++step) {
    MlpTrace t;
    forward(net, x, t);
    MlpGradient g(net);
    backward(net, t, 2.0f * (t.out.back() - y) / 64.0f, g);
    adam.step(net, g);
  }
  EXPECT_LT((net.layers[0].weight - a).cwiseAbs().maxCoeff(), 1e-2f);
}

}  // namespace
}  // namespace haptex::predict
