#include "predict/target_smoothing.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "tests/support/npy.hpp"

namespace haptex::predict {
namespace {

TEST(TargetSmoothing, AveragesTheNamedColumnsOverNeighbouringBinsWithTriangularWeights) {
  Eigen::MatrixXf t(6, 3);
  for (Eigen::Index c = 0; c < 3; ++c)
    for (Eigen::Index b = 0; b < 6; ++b) t(b, c) = float((b + 1) * (b + 1) + 10 * c);  // 1, 4, 9, 16, 25, 36
  const Eigen::MatrixXf three = smoothed_targets(t, {0, 2}, 3);
  EXPECT_FLOAT_EQ(three(0, 0), (2 * 1 + 4) / 3.0f);  // the band's first bin: weights 2, 1
  EXPECT_FLOAT_EQ(three(2, 0), (4 + 2 * 9 + 16) / 4.0f);
  EXPECT_FLOAT_EQ(three(5, 0), (25 + 2 * 36) / 3.0f);
  EXPECT_FLOAT_EQ(three(2, 2), (24 + 2 * 29 + 36) / 4.0f);
  EXPECT_EQ(three.col(1), t.col(1)) << "columns not named are kept";
  const Eigen::MatrixXf five = smoothed_targets(t, {0}, 5);
  EXPECT_FLOAT_EQ(five(1, 0), (2 * 1 + 3 * 4 + 2 * 9 + 16) / 8.0f);
  EXPECT_FLOAT_EQ(five(3, 0), (4 + 2 * 9 + 3 * 16 + 2 * 25 + 36) / 9.0f);
  EXPECT_EQ(smoothed_targets(t, {0, 1, 2}, 1), t);
}

TEST(TargetSmoothing, RefusesAnEvenOrNonPositiveWidth) {
  const Eigen::MatrixXf t = Eigen::MatrixXf::Ones(4, 2);
  for (int bins : {0, 2, 4, -1}) EXPECT_THROW(smoothed_targets(t, {0}, bins), Error) << bins;
}

// Windows of noise-like vibration: every bin Rayleigh-distributed around a smooth expected spectrum
// (a resonance 60 Hz wide on a floor). Smoothed over 3 bins, the targets are nearer their expectation:
// the scatter drops to (1 + 4 + 1) / 16 of its variance, while the resonance bends too slowly to matter.
TEST(TargetSmoothing, BringsRayleighScatteredSpectraNearerTheirExpectation) {
  const Eigen::Index bins = 100, windows = 2000;
  Eigen::VectorXf expected(bins);
  for (Eigen::Index k = 0; k < bins; ++k) expected[k] = float(0.1 + std::exp(-0.5 * std::pow((k - 40) / 6.0, 2)));
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> uniform(1e-12, 1.0);
  Eigen::MatrixXf t(bins, windows);
  std::vector<std::size_t> all;
  for (Eigen::Index c = 0; c < windows; ++c) {
    for (Eigen::Index k = 0; k < bins; ++k)  // Rayleigh with mean expected[k]
      t(k, c) = float(expected[k] * std::sqrt(2.0 / M_PI) * std::sqrt(-2.0 * std::log(uniform(rng))));
    all.push_back(std::size_t(c));
  }
  const Eigen::MatrixXf s = smoothed_targets(t, all, 3);
  const double raw = (t.colwise() - expected).squaredNorm(), smooth = (s.colwise() - expected).squaredNorm();
  EXPECT_NEAR(raw / (windows * expected.squaredNorm()), 4 / M_PI - 1, 0.01) << "Rayleigh: variance (4/pi - 1) mean^2";
  EXPECT_LT(smooth / raw, 0.40) << smooth / raw;
  EXPECT_GT(smooth / raw, 0.36) << "inside the band no better than the kernel's 0.375 allows";
}

// Against numpy's reading of the documented definition (tests/golden/target_smoothing_golden.py), the
// same reference python/haptex/smoothing.py is checked against, so C++ and Python smooth alike.
TEST(TargetSmoothing, MatchesTheNumpyReference) {
  const test::NpyArray input = test::load_golden("target_smoothing/input.npy");  // windows x bins
  Eigen::MatrixXf t(Eigen::Index(input.cols()), Eigen::Index(input.rows()));
  std::vector<std::size_t> all;
  for (std::size_t w = 0; w < input.rows(); ++w) {
    all.push_back(w);
    for (std::size_t b = 0; b < input.cols(); ++b) t(Eigen::Index(b), Eigen::Index(w)) = float(input.at(w, b));
  }
  for (const int bins : {1, 3, 5, 7, 9, 201}) {
    const test::NpyArray reference = test::load_golden("target_smoothing/bins_" + std::to_string(bins) + ".npy");
    const Eigen::MatrixXf s = smoothed_targets(t, all, bins);
    std::vector<double> got, want;
    for (std::size_t w = 0; w < input.rows(); ++w)
      for (std::size_t b = 0; b < input.cols(); ++b) got.push_back(s(Eigen::Index(b), Eigen::Index(w))), want.push_back(reference.at(w, b));
    EXPECT_LT(test::max_scaled_error(got, want), 2e-6) << bins << " bins";
  }
}

}  // namespace
}  // namespace haptex::predict
