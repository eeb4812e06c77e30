#include "core/ar/lsf.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "core/ar/poles.hpp"
#include "core/error.hpp"
#include "tests/support/npy.hpp"

namespace haptex::ar {
namespace {

double max_abs_diff(const std::vector<double>& a, const std::vector<double>& b) {
  EXPECT_EQ(a.size(), b.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) worst = std::max(worst, std::abs(a[i] - b[i]));
  return worst;
}

std::string order_name(int order) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%02d", order);
  return buf;
}

// numpy's poly2lsf/lsf2poly (np.roots, MATLAB's algorithm) on random stable polynomials.
TEST(ArLsf, MatchesNumpyGolden) {
  for (int order : {5, 8, 13, 20}) {
    SCOPED_TRACE("order " + std::to_string(order));
    const auto poly = test::load_golden("ar/lsf_poly_order" + order_name(order) + ".npy").data;
    const auto lsf = test::load_golden("ar/lsf_order" + order_name(order) + ".npy").data;
    ASSERT_EQ(lsf.size(), std::size_t(order));
    EXPECT_LT(max_abs_diff(poly_to_lsf(poly), lsf), 1e-9);
    EXPECT_LT(max_abs_diff(lsf_to_poly(lsf), poly), 1e-9);
  }
}

TEST(ArLsf, FirstOrderIsTheArccosine) {
  // A(z) = 1 - 0.5 z^-1: Q1 = 1 - z^-1 + z^-2 -> 2 cos(w) - 1 = 0 at w = pi / 3.
  const std::vector<double> a{1.0, -0.5};
  const auto lsf = poly_to_lsf(a);
  ASSERT_EQ(lsf.size(), 1u);
  EXPECT_NEAR(lsf[0], std::numbers::pi / 3.0, 1e-15);
  EXPECT_LT(max_abs_diff(lsf_to_poly(lsf), a), 1e-15);
}

TEST(ArLsf, LeadingCoefficientIsDividedOut) {
  const std::vector<double> a{1.0, -0.9, 0.5, 0.1};
  const std::vector<double> scaled{2.0, -1.8, 1.0, 0.2};
  EXPECT_LT(max_abs_diff(poly_to_lsf(scaled), poly_to_lsf(a)), 1e-14);
}

// Random LSF sets of orders 1..24 with HaTT-like spacing (its closest pair is 0.0086 rad apart):
// LSF -> polynomial -> LSF within 1e-9, and the polynomial is stable.
TEST(ArLsf, RandomRoundTrips) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> gap(0.3, 1.7);
  double worst = 0.0;
  for (int order = 1; order <= 24; ++order) {
    for (int trial = 0; trial < 50; ++trial) {
      std::vector<double> gaps(order + 1);
      double total = 0.0;
      for (double& g : gaps) total += (g = gap(rng));
      std::vector<double> lsf(order);
      double w = 0.0;
      for (int i = 0; i < order; ++i) lsf[i] = (w += gaps[i] * std::numbers::pi / total);
      const auto a = lsf_to_poly(lsf);
      EXPECT_LT(max_pole_radius(a), 1.0);
      worst = std::max(worst, max_abs_diff(poly_to_lsf(a), lsf));
    }
  }
  EXPECT_LT(worst, 1e-9);
}

// Unconstrained random LSFs cluster; the polynomial's coefficients then pin the LSFs down only
// loosely (a root's error is the coefficient rounding over the product of distances to its
// neighbours), so the round trip is looser (numpy's np.roots route lands as far off on the same
// polynomials: 1.7e-4 at worst here), but every LSF is still found and the filter is stable.
TEST(ArLsf, ClusteredRandomLsfs) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(0.0, std::numbers::pi);
  for (int order = 1; order <= 24; ++order) {
    for (int trial = 0; trial < 20; ++trial) {
      std::vector<double> lsf(order);
      for (double& w : lsf) w = unit(rng);
      std::sort(lsf.begin(), lsf.end());
      if (std::adjacent_find(lsf.begin(), lsf.end()) != lsf.end()) continue;
      const auto a = lsf_to_poly(lsf);
      EXPECT_LT(max_pole_radius(a), 1.0);
      EXPECT_LT(max_abs_diff(poly_to_lsf(a), lsf), 1e-3) << "order " << order;
    }
  }
}

// Closely spaced LSFs put poles right next to the unit circle; the grid search must still find them.
TEST(ArLsf, NearlyCoincidentLsfs) {
  const std::vector<double> lsf{0.05, 0.0500001, 1.5, 1.5000002, 3.1, 3.1000001};
  const auto a = lsf_to_poly(lsf);
  EXPECT_LT(max_pole_radius(a), 1.0);
  EXPECT_LT(max_abs_diff(poly_to_lsf(a), lsf), 1e-9);
}

TEST(ArLsf, RefusesUnstablePolynomials) {
  EXPECT_THROW(poly_to_lsf(std::vector<double>{1.0, -1.5}), Error);           // real root at 1.5
  EXPECT_THROW(poly_to_lsf(std::vector<double>{1.0, 0.0, 1.44}), Error);      // roots +-1.2j
  EXPECT_THROW(poly_to_lsf(std::vector<double>{1.0, 0.0, 1.0}), Error);       // roots on the circle
  EXPECT_THROW(poly_to_lsf(std::vector<double>{1.0, -2.2, 1.4, 0.1}), Error);  // |z|^2 ~ 1.4
  EXPECT_THROW(poly_to_lsf(std::vector<double>{1.0}), Error);
  EXPECT_THROW(poly_to_lsf(std::vector<double>{0.0, 1.0}), Error);
  try {
    poly_to_lsf(std::vector<double>{1.0, 0.0, 1.44});
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("unit circle"), std::string::npos) << e.what();
  }
}

TEST(ArLsf, RefusesBadLsfs) {
  const double pi = std::numbers::pi;
  EXPECT_THROW(lsf_to_poly(std::vector<double>{0.5, 0.4, 1.0}), Error);  // decreasing
  EXPECT_THROW(lsf_to_poly(std::vector<double>{0.5, 0.5}), Error);       // repeated
  EXPECT_THROW(lsf_to_poly(std::vector<double>{0.0, 1.0}), Error);       // on z = 1
  EXPECT_THROW(lsf_to_poly(std::vector<double>{1.0, pi}), Error);        // on z = -1
  EXPECT_THROW(lsf_to_poly(std::vector<double>{1.0, NAN}), Error);
  EXPECT_THROW(lsf_to_poly(std::vector<double>{}), Error);
  try {
    lsf_to_poly(std::vector<double>{0.5, 0.4, 1.0});
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("value 2"), std::string::npos) << e.what();
  }
}

TEST(ArLsf, UncheckedVersionReusesBuffers) {
  const std::vector<double> lsf{0.3, 0.9, 1.2, 2.0, 2.9};
  std::vector<double> a, work;
  lsf_to_poly_unchecked(lsf, a, work);
  const double* before = a.data();
  lsf_to_poly_unchecked(lsf, a, work);
  EXPECT_EQ(a.data(), before);
  EXPECT_EQ(a, lsf_to_poly(lsf));
}

}  // namespace
}  // namespace haptex::ar
