#include "evaluate/measures/summary_statistics.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "tests/support/npy.hpp"

namespace haptex::evaluate {
namespace {

using test::load_golden;
using test::max_scaled_error;

const char* const kSamples[] = {"one", "two", "ties", "ten", "many"};

std::vector<double> sample(const std::string& name) { return load_golden("evaluate/percentile_" + name + "_x.npy").data; }

TEST(EvaluateSummaryStatistics, PercentilesMatchNumpyLinear) {
  const auto q = load_golden("evaluate/percentile_q.npy").data;
  for (const std::string name : kSamples) {
    const auto expected = load_golden("evaluate/percentile_" + name + "_expected.npy").data;
    EXPECT_LT(max_scaled_error(percentiles(sample(name), q), expected), 1e-14) << name;
    for (std::size_t i = 0; i < q.size(); ++i)
      EXPECT_NEAR(percentile(sample(name), q[i]), expected[i], 1e-14 * std::abs(expected[i])) << name << " q " << q[i];
  }
}

TEST(EvaluateSummaryStatistics, QuartilesMatchNumpy) {
  for (const std::string name : kSamples) {
    const auto expected = load_golden("evaluate/quartiles_" + name + "_expected.npy").data;
    const auto q = quartiles(sample(name));
    EXPECT_LT(max_scaled_error({q.q1, q.median, q.q3}, expected), 1e-14) << name;
  }
}

TEST(EvaluateSummaryStatistics, MeanMatchesNumpy) {
  for (const std::string name : kSamples) {
    const double expected = load_golden("evaluate/mean_" + name + "_expected.npy").data.at(0);
    EXPECT_NEAR(mean(sample(name)), expected, 1e-13 * std::abs(expected)) << name;
  }
}

// The input order does not matter: percentiles sort a copy.
TEST(EvaluateSummaryStatistics, InputOrderDoesNotMatter) {
  auto x = sample("many");
  const auto before = quartiles(x);
  std::reverse(x.begin(), x.end());
  const auto after = quartiles(x);
  EXPECT_EQ(before.q1, after.q1);
  EXPECT_EQ(before.median, after.median);
  EXPECT_EQ(before.q3, after.q3);
}

TEST(EvaluateSummaryStatistics, RejectsEmptyNonFiniteAndBadQ) {
  const std::vector<double> none, x{1.0, 2.0, 3.0}, with_nan{1.0, std::nan("")};
  EXPECT_THROW(mean(none), Error);
  EXPECT_THROW(quartiles(none), Error);
  EXPECT_THROW(percentile(none, 50.0), Error);
  EXPECT_THROW(mean(with_nan), Error);
  EXPECT_THROW(quartiles(with_nan), Error);
  EXPECT_THROW(sample_variance(std::vector<double>{1.0}), Error);
  EXPECT_THROW(percentile(x, -0.1), Error);
  EXPECT_THROW(percentile(x, 100.1), Error);
  EXPECT_THROW(percentile(x, std::numeric_limits<double>::quiet_NaN()), Error);
}

}  // namespace
}  // namespace haptex::evaluate
