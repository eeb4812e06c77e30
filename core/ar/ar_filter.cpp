#include "core/ar/ar_filter.hpp"

#include <algorithm>
#include <cmath>

#include "core/ar/gaussian_noise.hpp"
#include "core/ar/poles.hpp"
#include "core/error.hpp"

namespace haptex::ar {

double AllPoleFilter::step(std::span<const double> a, double excitation) {
  const std::size_t p = a.empty() ? 0 : a.size() - 1;
  if (history_.size() < p) history_.resize(p, 0.0);
  double y = excitation;
  for (std::size_t i = 0; i < p; ++i) y -= a[i + 1] * history_[i];
  // Newest first; p is at most ~20 for HaTT, so shifting beats a ring buffer's bookkeeping.
  if (!history_.empty()) {
    std::copy_backward(history_.begin(), history_.end() - 1, history_.end());
    history_[0] = y;
  }
  return y;
}

void AllPoleFilter::reset() { std::fill(history_.begin(), history_.end(), 0.0); }

std::vector<double> all_pole_filter(std::span<const double> a, std::span<const double> excitation) {
  AllPoleFilter filter;
  std::vector<double> y(excitation.size());
  for (std::size_t n = 0; n < y.size(); ++n) y[n] = filter.step(a, excitation[n]);
  return y;
}

std::vector<double> synthesize_ar(std::span<const double> a, double variance, std::size_t n, std::uint64_t seed) {
  if (!std::isfinite(variance) || variance < 0.0)
    throw failure("synthesize_ar: the excitation variance must be finite and >= 0");
  if (a.empty() || a[0] != 1.0) throw failure("synthesize_ar: a must start with a leading 1");
  if (!(max_pole_radius(a) < 1.0))
    throw failure("synthesize_ar: the AR filter is unstable (a pole on or outside the unit circle)");
  GaussianNoise noise(seed);
  AllPoleFilter filter;
  const double sigma = std::sqrt(variance);
  std::vector<double> y(n);
  for (double& v : y) v = filter.step(a, sigma * noise.next());
  return y;
}

}  // namespace haptex::ar
