#include "evaluate/measures/welch_test.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "tests/support/npy.hpp"

namespace haptex::evaluate {
namespace {

using test::load_golden;

struct Case {
  std::vector<double> a, b;
  std::vector<double> expected;  // scipy: t, df, p, mean_a, mean_b
};

Case load_case(const std::string& name) {
  return {load_golden("evaluate/welch_" + name + "_a.npy").data, load_golden("evaluate/welch_" + name + "_b.npy").data,
          load_golden("evaluate/welch_" + name + "_expected.npy").data};
}

// Relative agreement; a reference of exactly 0 must be met exactly.
void expect_relative(double got, double expected, double tolerance, const std::string& what) {
  EXPECT_NEAR(got, expected, tolerance * std::abs(expected)) << what;
}

TEST(EvaluateWelch, MatchesScipyTtestInd) {
  for (const std::string name : {"sleep", "docs_equal", "docs_unequal", "one_zero_variance", "tiny", "unequal_n",
                                 "huge_t", "identical"}) {
    const auto c = load_case(name);
    const auto r = welch_t_test(c.a, c.b);
    expect_relative(r.t, c.expected[0], 1e-10, name + " t");
    expect_relative(r.df, c.expected[1], 1e-10, name + " df");
    expect_relative(r.p, c.expected[2], 1e-10, name + " p");
    expect_relative(r.mean_a, c.expected[3], 1e-13, name + " mean a");
    expect_relative(r.mean_b, c.expected[4], 1e-13, name + " mean b");
    EXPECT_EQ(r.n_a, c.a.size()) << name;
    EXPECT_EQ(r.n_b, c.b.size()) << name;
  }
}

// The golden case is built so that p is near the bottom of the double range, not 0.
TEST(EvaluateWelch, HugeTKeepsATinyNonZeroP) {
  const auto c = load_case("huge_t");
  const auto r = welch_t_test(c.a, c.b);
  EXPECT_GT(r.p, 0.0);
  EXPECT_LT(r.p, 1e-290);
}

// scipy returns t = p = nan here; haptex defines t = 0, p = 1 and keeps scipy's df placeholder.
TEST(EvaluateWelch, BothWithoutSpreadAndEqualMeans) {
  const auto c = load_case("both_zero_equal");
  ASSERT_TRUE(std::isnan(c.expected[0]) && std::isnan(c.expected[2])) << "scipy's behaviour changed";
  const auto r = welch_t_test(c.a, c.b);
  EXPECT_EQ(r.t, 0.0);
  EXPECT_EQ(r.p, 1.0);
  EXPECT_EQ(r.df, c.expected[1]);
  EXPECT_EQ(r.mean_a, c.expected[3]);
}

// scipy returns t = -inf, p = 0: kept.
TEST(EvaluateWelch, BothWithoutSpreadAndDifferentMeans) {
  const auto c = load_case("both_zero_unequal");
  const auto r = welch_t_test(c.a, c.b);
  EXPECT_EQ(r.t, c.expected[0]);
  EXPECT_TRUE(std::isinf(r.t) && r.t < 0);
  EXPECT_EQ(r.p, c.expected[2]);
  EXPECT_EQ(r.df, c.expected[1]);
  const auto swapped = welch_t_test(c.b, c.a);
  EXPECT_EQ(swapped.t, std::numeric_limits<double>::infinity());
  EXPECT_EQ(swapped.p, 0.0);
}

TEST(EvaluateWelch, SwappingSamplesNegatesT) {
  const auto c = load_case("docs_unequal");
  const auto ab = welch_t_test(c.a, c.b), ba = welch_t_test(c.b, c.a);
  EXPECT_EQ(ab.t, -ba.t);
  EXPECT_EQ(ab.p, ba.p);
  EXPECT_EQ(ab.df, ba.df);
}

// Distances of any size: the test is scale-free, and squaring variances of 1e160 must not overflow
// the degrees of freedom into NaN (a model file with amplitudes of 1e80 did that once).
TEST(EvaluateWelch, HugeDistancesGiveTheScaledTest) {
  const auto c = load_case("docs_unequal");
  std::vector<double> a = c.a, b = c.b;
  for (double& x : a) x *= 1e150;
  for (double& x : b) x *= 1e150;
  const auto small = welch_t_test(c.a, c.b), huge = welch_t_test(a, b);
  EXPECT_NEAR(huge.df, small.df, 1e-9 * small.df);
  EXPECT_NEAR(huge.t, small.t, 1e-9 * std::abs(small.t));
  EXPECT_NEAR(huge.p, small.p, 1e-9);
}

TEST(EvaluateWelch, RejectsTooSmallOrNonFiniteSamples) {
  const std::vector<double> one{1.0}, two{1.0, 2.0}, none;
  EXPECT_THROW(welch_t_test(one, two), Error);
  EXPECT_THROW(welch_t_test(two, one), Error);
  EXPECT_THROW(welch_t_test(none, two), Error);
  const std::vector<double> with_nan{1.0, std::nan(""), 3.0}, with_inf{1.0, std::numeric_limits<double>::infinity()};
  EXPECT_THROW(welch_t_test(with_nan, two), Error);
  EXPECT_THROW(welch_t_test(two, with_inf), Error);
}

}  // namespace
}  // namespace haptex::evaluate
