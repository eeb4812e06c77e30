#include "evaluate/measures/welch_test.hpp"

#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.hpp"
#include "evaluate/measures/summary_statistics.hpp"

namespace haptex::evaluate {
namespace {

// Welch-Satterthwaite; 1 where both variances are zero (0/0), as scipy substitutes. Written in the
// variances' shares of their sum, which no size of distance overflows.
double welch_df(double va_n, double vb_n, std::size_t n_a, std::size_t n_b) {
  const double sum = va_n + vb_n;
  if (sum == 0.0) return 1.0;
  const double a = va_n / sum, b = vb_n / sum;
  return 1.0 / (a * a / static_cast<double>(n_a - 1) + b * b / static_cast<double>(n_b - 1));
}

double two_sided_p(double t, double df) {
  if (std::isinf(t)) return 0.0;
  const boost::math::students_t distribution(df);
  return 2.0 * boost::math::cdf(boost::math::complement(distribution, std::abs(t)));
}

void check_size(std::span<const double> x, const char* name) {
  if (x.size() < 2)
    throw failure(std::string("Welch's t-test: sample ") + name + " has " + std::to_string(x.size()) +
                  " value(s); each sample needs at least 2 for its variance");
}

}  // namespace

WelchTest welch_t_test(std::span<const double> a, std::span<const double> b) {
  check_size(a, "a");
  check_size(b, "b");
  WelchTest result;
  result.n_a = a.size();
  result.n_b = b.size();
  const double va_n = sample_variance(a) / static_cast<double>(a.size());  // checks finiteness
  const double vb_n = sample_variance(b) / static_cast<double>(b.size());
  result.mean_a = mean(a);
  result.mean_b = mean(b);
  result.df = welch_df(va_n, vb_n, a.size(), b.size());
  const double difference = result.mean_a - result.mean_b;
  const double spread = std::sqrt(va_n + vb_n);
  if (spread == 0.0) {
    // No spread in either sample: the means alone decide.
    result.t = difference == 0.0 ? 0.0 : std::copysign(std::numeric_limits<double>::infinity(), difference);
  } else {
    result.t = difference / spread;
  }
  result.p = two_sided_p(result.t, result.df);
  return result;
}

}  // namespace haptex::evaluate
