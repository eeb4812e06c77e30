#include "core/ar/burg.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"

namespace haptex::ar {
namespace {

void check_input(std::span<const double> x, std::size_t order) {
  if (order < 1) throw failure("burg: the AR order must be at least 1");
  if (x.size() <= order)
    throw failure("burg: " + std::to_string(x.size()) + " samples cannot fit an AR(" + std::to_string(order) +
                  ") model; give more samples than the order");
  for (double v : x)
    if (!std::isfinite(v)) throw failure("burg: the signal contains NaN or infinity");
}

}  // namespace

ArFit burg(std::span<const double> x, std::size_t order) {
  check_input(x, order);
  const std::size_t n = x.size();
  // f[t], b[t]: forward and backward prediction errors at time t, updated in place stage by stage.
  std::vector<double> f(x.begin(), x.end()), b(x.begin(), x.end());
  ArFit fit;
  fit.a.assign(1, 1.0);
  double energy = 0.0;
  for (double v : x) energy += v * v;
  fit.variance = energy / double(n);
  for (std::size_t m = 1; m <= order; ++m) {
    double num = 0.0, den = 0.0;
    for (std::size_t t = m; t < n; ++t) {
      num += b[t - 1] * f[t];
      den += f[t] * f[t] + b[t - 1] * b[t - 1];
    }
    if (!(den > 0.0)) throw failure("burg: the signal is identically zero; there is nothing to model");
    const double k = -2.0 * num / den;
    // Descending t: b[t - 1] still holds stage m - 1 when f[t] and b[t] are updated.
    for (std::size_t t = n - 1; t >= m; --t) {
      const double ft = f[t], bt = b[t - 1];
      f[t] = ft + k * bt;
      b[t] = bt + k * ft;
    }
    std::vector<double> next(m + 1);
    for (std::size_t i = 0; i < m; ++i) next[i] = fit.a[i] + (i == 0 ? 0.0 : k * fit.a[m - i]);
    next[m] = k;
    fit.a = std::move(next);
    fit.reflection.push_back(k);
    fit.variance *= 1.0 - k * k;
  }
  return fit;
}

}  // namespace haptex::ar
