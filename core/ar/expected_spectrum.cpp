#include "core/ar/expected_spectrum.hpp"

#include <cmath>
#include <map>
#include <numbers>
#include <string>

#include "core/error.hpp"

namespace haptex::ar {
namespace {

// Reflection coefficients k_1..k_p of a = [1, a1..ap] by the step-down recursion.
std::vector<double> reflection_coefficients(std::span<const double> a) {
  const std::size_t p = a.size() - 1;
  std::vector<double> cur(a.begin(), a.end()), k(p + 1, 0.0);
  for (std::size_t m = p; m >= 1; --m) {
    k[m] = cur[m];
    if (!(std::fabs(k[m]) < 1.0))
      throw failure("expected spectrum: the AR filter is not stable (reflection coefficient " + std::to_string(m) + " is " +
                    std::to_string(k[m]) + "); give a model whose poles lie inside the unit circle");
    const double scale = 1.0 - k[m] * k[m];
    std::vector<double> next(m, 0.0);
    next[0] = 1.0;
    for (std::size_t i = 1; i < m; ++i) next[i] = (cur[i] - k[m] * cur[m - i]) / scale;
    cur = std::move(next);
  }
  return k;
}

}  // namespace

std::vector<double> ar_autocorrelation(std::span<const double> a, double variance, std::size_t lags) {
  if (a.empty() || a[0] != 1.0) throw failure("expected spectrum: AR coefficients must start with a0 = 1");
  for (double v : a)
    if (!std::isfinite(v)) throw failure("expected spectrum: an AR coefficient is not finite");
  if (!std::isfinite(variance) || variance < 0.0)
    throw failure("expected spectrum: the excitation variance " + std::to_string(variance) + " is not a finite value >= 0");
  std::vector<double> r(lags, 0.0);
  const std::size_t p = a.size() - 1;
  const std::vector<double> k = reflection_coefficients(a);
  if (lags == 0 || variance == 0.0) return r;
  double gain = 1.0;
  for (std::size_t m = 1; m <= p; ++m) gain *= 1.0 - k[m] * k[m];
  // Levinson up-recursion: order-m predictor poly[0..m] and its error power, giving r[m].
  std::vector<double> poly{1.0};
  double error = variance / gain;
  r[0] = error;
  for (std::size_t m = 1; m <= p && m < lags; ++m) {
    double sum = 0.0;
    for (std::size_t i = 1; i < m; ++i) sum += poly[i] * r[m - i];
    r[m] = -k[m] * error - sum;
    std::vector<double> next(m + 1, 0.0);
    next[0] = 1.0;
    for (std::size_t i = 1; i < m; ++i) next[i] = poly[i] + k[m] * poly[m - i];
    next[m] = k[m];
    poly = std::move(next);
    error *= 1.0 - k[m] * k[m];
  }
  // Beyond the order, the Yule-Walker equations extend r.
  for (std::size_t m = p + 1; m < lags; ++m) {
    double sum = 0.0;
    for (std::size_t i = 1; i <= p; ++i) sum += a[i] * r[m - i];
    r[m] = -sum;
  }
  return r;
}

void windowed_power(std::span<const double> r, std::span<double> out, std::size_t first_bin) {
  const std::size_t n = r.size();
  if (n == 0) throw failure("expected spectrum: empty autocorrelation");
  if (!out.empty() && 2 * (first_bin + out.size() - 1) > n)
    throw failure("expected spectrum: bins up to " + std::to_string(first_bin + out.size() - 1) + " pass N/2 = " + std::to_string(n / 2));
  for (std::size_t b = 0; b < out.size(); ++b) {
    const double w = 2.0 * std::numbers::pi * double(first_bin + b) / double(n);
    double sum = double(n) * r[0];
    for (std::size_t m = 1; m < n; ++m) sum += 2.0 * double(n - m) * r[m] * std::cos(w * double(m));
    out[b] = sum;
  }
}

namespace {

void check_options(const ExpectedSpectrumOptions& o) {
  if (o.window < 2 || o.bins == 0 || 2 * o.bins > o.window || o.update == 0 || o.update > o.window ||
      !std::isfinite(o.noise_power) || o.noise_power < 0.0)
    throw failure("expected spectrum: options out of range (window " + std::to_string(o.window) + ", bins " +
                  std::to_string(o.bins) + ", update " + std::to_string(o.update) +
                  "); give bins <= window/2, 0 < update <= window and a finite noise power >= 0");
}

// (N - m)-weighted cosine table, bins x lags: windowed_power as one dot product per bin.
std::vector<std::vector<double>> weighted_cosines(const ExpectedSpectrumOptions& o) {
  std::vector<std::vector<double>> table(o.bins, std::vector<double>(o.window));
  for (std::size_t b = 0; b < o.bins; ++b) {
    const double w = 2.0 * std::numbers::pi * double(b + 1) / double(o.window);
    table[b][0] = double(o.window);
    for (std::size_t m = 1; m < o.window; ++m) table[b][m] = 2.0 * double(o.window - m) * std::cos(w * double(m));
  }
  return table;
}

}  // namespace

std::vector<std::vector<double>> expected_window_spectra(const PiecewiseArModel& model, std::span<const double> speed,
                                                         std::span<const double> force,
                                                         std::span<const std::size_t> starts,
                                                         const ExpectedSpectrumOptions& options) {
  check_options(options);
  if (speed.size() != force.size())
    throw failure("expected spectrum: speed has " + std::to_string(speed.size()) + " samples but force has " +
                  std::to_string(force.size()) + "; give one force per speed sample");
  const std::size_t n = options.window, updates = (n + options.update - 1) / options.update;
  const auto cosines = weighted_cosines(options);
  std::map<std::size_t, std::vector<double>> cache;  // autocorrelation per blend sample
  std::vector<std::vector<double>> spectra;
  spectra.reserve(starts.size());
  for (std::size_t start : starts) {
    if (start > speed.size() || speed.size() - start < n)
      throw failure("expected spectrum: the window at sample " + std::to_string(start) + " leaves the " +
                    std::to_string(speed.size()) + "-sample action");
    // Windows come in order in practice: forget the blends before this one.
    cache.erase(cache.begin(), cache.lower_bound(start));
    std::vector<double> r(n, 0.0);
    for (std::size_t u = 0; u < updates; ++u) {
      const std::size_t t = std::min(start + options.update / 2 + u * options.update, start + n - 1);
      auto it = cache.find(t);
      if (it == cache.end()) {
        if (!std::isfinite(speed[t]) || !std::isfinite(force[t]))
          throw failure("expected spectrum: the action at sample " + std::to_string(t) + " is not finite");
        const BlendedAr blend = model.blend(speed[t], force[t]);
        it = cache.emplace(t, ar_autocorrelation(blend.a, blend.variance, n)).first;
      }
      for (std::size_t m = 0; m < n; ++m) r[m] += it->second[m] / double(updates);
    }
    std::vector<double> amplitude(options.bins);
    for (std::size_t b = 0; b < options.bins; ++b) {
      double power = double(n) * options.noise_power;
      for (std::size_t m = 0; m < n; ++m) power += cosines[b][m] * r[m];
      amplitude[b] = 2.0 / double(n) * std::sqrt(std::numbers::pi / 4.0 * std::max(power, 0.0));
    }
    spectra.push_back(std::move(amplitude));
  }
  return spectra;
}

}  // namespace haptex::ar
