#pragma once
// Summary statistics of per-window losses and of test results, computed the way numpy does, so a
// report's numbers can be checked against a few lines of numpy.
#include <span>
#include <vector>

namespace haptex::evaluate {

// Arithmetic mean. Throws haptex::Error for an empty sample or a value that is not finite.
double mean(std::span<const double> x);

// Sample variance with n - 1 in the denominator (numpy.var(x, ddof=1)), two-pass as numpy computes it.
// Throws haptex::Error for fewer than 2 values or a value that is not finite.
double sample_variance(std::span<const double> x);

// numpy.percentile(x, q) with the default method='linear': sorted x, position q/100 * (n - 1),
// linear interpolation between its neighbours. q in [0, 100]. Throws haptex::Error for an empty
// sample, a value that is not finite, or q outside [0, 100].
double percentile(std::span<const double> x, double q);
// The same for several q at once (x is sorted once).
std::vector<double> percentiles(std::span<const double> x, std::span<const double> q);

struct Quartiles {
  double q1 = 0.0, median = 0.0, q3 = 0.0;
};
// numpy.percentile(x, [25, 50, 75]).
Quartiles quartiles(std::span<const double> x);

}  // namespace haptex::evaluate
