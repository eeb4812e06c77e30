#include "qa/band_power.hpp"

#include <cmath>
#include <complex>
#include <numbers>
#include <numeric>
#include <vector>

#include "core/signal/fft.hpp"

namespace haptex::qa {

BandPower band_power(std::span<const double> x, double sample_rate_hz, double low_hz, double high_hz) {
  const std::size_t n = x.size();
  if (n < 2) return {};
  const double mean = std::accumulate(x.begin(), x.end(), 0.0) / double(n);
  std::vector<double> windowed(n);
  double window_power = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double w = 0.5 - 0.5 * std::cos(2 * std::numbers::pi * double(i) / double(n));
    windowed[i] = w * (x[i] - mean);
    window_power += w * w;
  }
  // One transform per length, made once: recordings of a file mostly share their length.
  const auto& fft = signal::real_fft<double>(n);
  std::vector<std::complex<double>> spectrum(fft.bins());
  fft.forward(windowed, spectrum);
  BandPower p;
  const double scale = 2.0 / (double(n) * window_power);  // one-sided bins carry half the energy each
  for (std::size_t k = 1; k < spectrum.size(); ++k) {
    const double power = std::norm(spectrum[k]) * scale;
    p.total += power;
    const double f = double(k) * sample_rate_hz / double(n);
    if (f >= low_hz && f <= high_hz) p.band += power;
  }
  return p;
}

}  // namespace haptex::qa
