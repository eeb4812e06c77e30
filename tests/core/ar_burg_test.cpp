#include "core/ar/burg.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/ar/ar_filter.hpp"
#include "core/ar/gaussian_noise.hpp"
#include "core/error.hpp"
#include "tests/support/npy.hpp"

namespace haptex::ar {
namespace {

// tests/golden/ar_golden.py runs MATLAB's arburg recursion in numpy on a 20000-sample AR(5) path.
TEST(ArBurg, MatchesNumpyArburg) {
  const auto x = test::load_golden("ar/burg_x.npy").data;
  ASSERT_EQ(x.size(), 20000u);
  for (std::size_t order : {5u, 8u}) {
    SCOPED_TRACE("order " + std::to_string(order));
    const auto golden = test::load_golden("ar/burg_order" + std::to_string(order) + ".npy").data;
    ASSERT_EQ(golden.size(), order + 2);
    const ArFit fit = burg(x, order);
    ASSERT_EQ(fit.a.size(), order + 1);
    EXPECT_EQ(fit.a[0], 1.0);
    for (std::size_t i = 0; i <= order; ++i) EXPECT_NEAR(fit.a[i], golden[i], 1e-6) << "a" << i;
    EXPECT_NEAR(fit.variance, golden[order + 1], 1e-6 * golden[order + 1]);
    EXPECT_EQ(fit.reflection.size(), order);
    EXPECT_EQ(fit.reflection.back(), fit.a.back());
  }
}

TEST(ArBurg, RecoversASynthesizedProcess) {
  const auto a_true = test::load_golden("ar/burg_true_a.npy").data;
  const double variance = 0.37;
  const auto y = synthesize_ar(a_true, variance, 200000, 42);
  const ArFit fit = burg(y, a_true.size() - 1);
  for (std::size_t i = 1; i < a_true.size(); ++i) EXPECT_NEAR(fit.a[i], a_true[i], 0.02) << "a" << i;
  EXPECT_NEAR(fit.variance, variance, 0.02 * variance);
}

TEST(ArBurg, RefusesBadInput) {
  const std::vector<double> x{1.0, -0.5, 0.25, 0.1};
  EXPECT_THROW(burg(x, 0), Error);
  EXPECT_THROW(burg(x, 4), Error);
  EXPECT_THROW(burg(std::vector<double>(10, 0.0), 2), Error);
  EXPECT_THROW(burg(std::vector<double>{1.0, NAN, 0.0, 1.0}, 1), Error);
  EXPECT_NO_THROW(burg(x, 3));
}

// scipy.signal.lfilter([1], a, e) from rest.
TEST(ArFilter, MatchesScipyLfilter) {
  const auto a = test::load_golden("ar/filter_a.npy").data;
  const auto e = test::load_golden("ar/filter_e.npy").data;
  const auto y = test::load_golden("ar/filter_y.npy").data;
  EXPECT_LT(test::max_scaled_error(all_pole_filter(a, e), y), 1e-12);
}

TEST(ArFilter, StateCarriesAcrossCalls) {
  const auto a = test::load_golden("ar/filter_a.npy").data;
  const auto e = test::load_golden("ar/filter_e.npy").data;
  const auto whole = all_pole_filter(a, e);
  AllPoleFilter filter;
  for (std::size_t n = 0; n < e.size(); ++n) ASSERT_EQ(filter.step(a, e[n]), whole[n]) << n;
  filter.reset();
  EXPECT_EQ(filter.step(a, e[0]), whole[0]);
}

TEST(ArSynthesis, DeterministicPerSeed) {
  const std::vector<double> a{1.0, -0.9, 0.4};
  const auto first = synthesize_ar(a, 2.0, 5000, 123);
  EXPECT_EQ(first, synthesize_ar(a, 2.0, 5000, 123));
  EXPECT_NE(first, synthesize_ar(a, 2.0, 5000, 124));
  EXPECT_THROW(synthesize_ar(std::vector<double>{1.0, -1.2}, 1.0, 10, 1), Error);  // pole at 1.2
  EXPECT_THROW(synthesize_ar(a, -1.0, 10, 1), Error);
}

TEST(ArSynthesis, NoiseIsStandardNormal) {
  GaussianNoise noise(99);
  const std::size_t n = 1'000'000;
  double sum = 0.0, sum2 = 0.0, sum4 = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double v = noise.next();
    sum += v;
    sum2 += v * v;
    sum4 += v * v * v * v;
  }
  EXPECT_NEAR(sum / n, 0.0, 0.005);
  EXPECT_NEAR(sum2 / n, 1.0, 0.005);
  EXPECT_NEAR(sum4 / n, 3.0, 0.05);  // Gaussian kurtosis
}

}  // namespace
}  // namespace haptex::ar
