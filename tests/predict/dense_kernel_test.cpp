// The per-query kernel against Eigen and the scalar formula it replaces, on sizes that leave partial
// blocks of rows (not a multiple of 8) and of columns (not a multiple of 4). On a CPU without AVX2
// both sides are Eigen's and the comparison still holds; the test says which kernel ran. Inputs as a
// ReLU leaves them (about half exactly zero: the kernel skips those columns) and all zero as well.
#include "predict/dense_kernel.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace haptex::predict {
namespace {

TEST(DenseKernel, EqualsEigenOnEverySizeAndOnAColumnBlock) {
  SCOPED_TRACE(dense_kernel_uses_avx2() ? "AVX2 and FMA kernel" : "Eigen kernel");
  std::mt19937 rng(5);
  std::normal_distribution<float> normal;
  enum class Input { dense, relu, zero };
  for (const auto& [m, n] : {std::pair{100, 256}, std::pair{256, 32}, std::pair{7, 3}, std::pair{33, 5}, std::pair{8, 4}, std::pair{1, 1}})
    for (const Activation a : {Activation::linear, Activation::relu, Activation::softplus})
      for (const Input input : {Input::dense, Input::relu, Input::zero}) {
        const Eigen::MatrixXf w = Eigen::MatrixXf::NullaryExpr(m, n + 6, [&] { return normal(rng); });
        Eigen::VectorXf x = Eigen::VectorXf::NullaryExpr(n, [&] { return normal(rng); });
        if (input == Input::relu) x = x.cwiseMax(0.0f);
        if (input == Input::zero) x.setZero();
        const Eigen::VectorXf b = Eigen::VectorXf::NullaryExpr(m, [&] { return normal(rng); });
        Eigen::MatrixXf expected = w.rightCols(n) * x + b;
        activate(a, expected);
        Eigen::VectorXf out(m);
        dense_column(w.rightCols(n), x, b, a, out);
        for (int i = 0; i < m; ++i)
          ASSERT_NEAR(out(i), expected(i, 0), 2e-5f * (1 + std::abs(expected(i, 0))))
              << m << " x " << n << ", row " << i << ", " << activation_name(a) << ", input " << int(input);
      }
}

TEST(DenseKernel, SoftplusWithinFloatPrecisionOfTheFormulaFromTinyToHuge) {
  Eigen::MatrixXf z(1, 4001);
  for (int i = 0; i < z.cols(); ++i) z(0, i) = -200.0f + 0.1f * float(i);  // e^-200 is below float's range
  Eigen::MatrixXf fast = z;
  activate_fast(Activation::softplus, fast);
  for (int i = 0; i < z.cols(); ++i) {
    const double exact = std::max(double(z(0, i)), 0.0) + std::log1p(std::exp(-std::abs(double(z(0, i)))));
    ASSERT_GE(fast(0, i), 0.0f) << "softplus(" << z(0, i) << ")";
    if (z(0, i) >= -87.0f) ASSERT_NEAR(fast(0, i), exact, 3e-7 * exact) << "softplus(" << z(0, i) << ")";
    else ASSERT_LE(fast(0, i), 2e-38f) << "softplus(" << z(0, i) << ")";
  }
}

}  // namespace
}  // namespace haptex::predict
