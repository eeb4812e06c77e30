#include "core/signal/resample.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>

#include "core/error.hpp"

namespace haptex::signal {
namespace {

// numpy.sinc: sin(pi x) / (pi x).
double sinc(double x) { return x == 0 ? 1.0 : std::sin(M_PI * x) / (M_PI * x); }

// scipy.signal.upfirdn's output length for a filter of `taps` (its _output_len).
std::size_t upfirdn_length(std::size_t taps, std::size_t n, std::size_t up, std::size_t down) {
  const std::size_t padded = n + (taps + (up - taps % up) % up) / up - 1;
  return (padded * up + down - 1) / down;
}

}  // namespace

std::vector<double> kaiser_lowpass(int taps, double cutoff, double beta) {
  if (taps < 1 || taps % 2 == 0 || !(cutoff > 0 && cutoff < 1))
    throw failure("internal: kaiser_lowpass needs an odd number of taps and 0 < cutoff < 1");
  std::vector<double> h(static_cast<std::size_t>(taps));
  const double middle = 0.5 * (taps - 1), norm = std::cyl_bessel_i(0.0, beta);
  for (int n = 0; n < taps; ++n) {
    const double m = n - middle, r = taps > 1 ? 2.0 * n / (taps - 1) - 1.0 : 0.0;
    const double window = std::cyl_bessel_i(0.0, beta * std::sqrt(std::max(0.0, 1.0 - r * r))) / norm;
    h[std::size_t(n)] = cutoff * sinc(cutoff * m) * window;
  }
  const double sum = std::accumulate(h.begin(), h.end(), 0.0);
  for (double& v : h) v /= sum;
  return h;
}

std::vector<double> resample_poly(std::span<const double> x, int up_in, int down_in) {
  if (up_in < 1 || down_in < 1) throw failure("internal: resample_poly needs up and down of 1 or more");
  const int g = std::gcd(up_in, down_in);
  const std::size_t up = std::size_t(up_in / g), down = std::size_t(down_in / g), n = x.size();
  if (up == 1 && down == 1) return {x.begin(), x.end()};
  const std::size_t n_out = (n * up + down - 1) / down;
  const std::size_t half = 10 * std::max(up, down);
  std::vector<double> taps = kaiser_lowpass(int(2 * half + 1), 1.0 / double(std::max(up, down)), 5.0);
  // Zero-padded in front so the output samples fall at the filter's centre (scipy's n_pre_pad).
  const std::size_t pre_pad = down - half % down, pre_remove = (half + pre_pad) / down;
  std::vector<double> h(pre_pad, 0.0);
  for (double v : taps) h.push_back(v * double(up));
  while (upfirdn_length(h.size(), n, up, down) < n_out + pre_remove) h.push_back(0.0);

  const double mean = n ? std::accumulate(x.begin(), x.end(), 0.0) / double(n) : 0.0;
  std::vector<double> y(n_out);
  for (std::size_t k = 0; k < n_out; ++k) {
    // Output k of upfirdn: sum over inputs i of h[m - i up] x[i], m = (k + pre_remove) down.
    const std::size_t m = (k + pre_remove) * down;
    const std::size_t first = m + 1 > h.size() ? (m + 1 - h.size() + up - 1) / up : 0;
    const std::size_t last = std::min(m / up, n ? n - 1 : 0);
    double sum = 0;
    for (std::size_t i = first; n && i <= last; ++i) sum += h[m - i * up] * (x[i] - mean);
    y[k] = sum + mean;
  }
  return y;
}

std::vector<double> interpolate_uniform(std::span<const double> times, std::span<const double> values, double start_s,
                                        double grid_hz, std::size_t count) {
  if (times.size() != values.size() || times.size() < 2 || !(grid_hz > 0) ||
      std::adjacent_find(times.begin(), times.end(), std::greater_equal<double>()) != times.end())
    throw failure("internal: interpolate_uniform needs as many strictly increasing times as values, two or more");
  std::vector<double> out(count);
  std::size_t j = 0;
  for (std::size_t k = 0; k < count; ++k) {
    const double t = start_s + double(k) / grid_hz;
    while (j + 2 < times.size() && times[j + 1] <= t) ++j;
    const double span = times[j + 1] - times[j];
    const double w = std::clamp((t - times[j]) / span, 0.0, 1.0);
    out[k] = values[j] + w * (values[j + 1] - values[j]);
  }
  return out;
}

}  // namespace haptex::signal
