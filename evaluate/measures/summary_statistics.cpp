#include "evaluate/measures/summary_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace haptex::evaluate {
namespace {

void check_sample(std::span<const double> x, std::size_t minimum, const char* what) {
  if (x.size() < minimum)
    throw failure(std::string(what) + ": the sample has " + std::to_string(x.size()) + " values, at least " +
                  std::to_string(minimum) + " are needed");
  for (std::size_t i = 0; i < x.size(); ++i)
    if (!std::isfinite(x[i]))
      throw failure(std::string(what) + ": value " + std::to_string(i) + " is " + std::to_string(x[i]) +
                    "; every value must be finite");
}

// numpy's _lerp: a + (b - a) t, but from b's side for t >= 0.5 so that t = 1 gives b exactly.
double lerp(double a, double b, double t) {
  const double diff = b - a;
  return t >= 0.5 ? b - diff * (1.0 - t) : a + diff * t;
}

double percentile_of_sorted(const std::vector<double>& sorted, double q) {
  if (!(q >= 0.0 && q <= 100.0))
    throw failure("percentile: q = " + std::to_string(q) + " is outside [0, 100]");
  const double position = (q / 100.0) * static_cast<double>(sorted.size() - 1);
  const double below = std::floor(position);
  const auto lower = static_cast<std::size_t>(below);
  const std::size_t upper = std::min(lower + 1, sorted.size() - 1);
  return lerp(sorted[lower], sorted[upper], position - below);
}

}  // namespace

double mean(std::span<const double> x) {
  check_sample(x, 1, "mean");
  double sum = 0.0;
  for (double v : x) sum += v;
  return sum / static_cast<double>(x.size());
}

double sample_variance(std::span<const double> x) {
  check_sample(x, 2, "sample variance");
  const double m = mean(x);
  double sum = 0.0;
  for (double v : x) sum += (v - m) * (v - m);
  return sum / static_cast<double>(x.size() - 1);
}

std::vector<double> percentiles(std::span<const double> x, std::span<const double> q) {
  check_sample(x, 1, "percentile");
  std::vector<double> sorted(x.begin(), x.end());
  std::sort(sorted.begin(), sorted.end());
  std::vector<double> out;
  out.reserve(q.size());
  for (double p : q) out.push_back(percentile_of_sorted(sorted, p));
  return out;
}

double percentile(std::span<const double> x, double q) { return percentiles(x, std::span(&q, 1)).front(); }

Quartiles quartiles(std::span<const double> x) {
  const double q[] = {25.0, 50.0, 75.0};
  const auto values = percentiles(x, q);
  return {values[0], values[1], values[2]};
}

}  // namespace haptex::evaluate
