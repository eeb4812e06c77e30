#pragma once
// Steady test spectra and the statistics of a rendered signal's windows, for the renderings that
// must vary like a recording (shaped noise, RTISI-LA with scatter).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <span>
#include <vector>

#include "core/signal/spectrum.hpp"
#include "dataset/window.hpp"
#include "render/target_magnitudes.hpp"

namespace haptex::render::test_windows {

// A coloured texture spectrum (m/s^2 per bin, 10..1000 Hz): a floor with a resonance at 300 Hz.
inline std::vector<double> texture(double scale) {
  std::vector<double> a(dataset::kTargetBins);
  for (std::size_t k = 0; k < a.size(); ++k) a[k] = scale * (0.01 + 0.05 * std::exp(-std::pow((double(k) - 29.0) / 8.0, 2)));
  return a;
}

inline MagnitudeFrames frames_of(const std::vector<double>& amplitudes, std::size_t frames) {
  std::vector<double> all;
  for (std::size_t m = 0; m < frames; ++m) all.insert(all.end(), amplitudes.begin(), amplitudes.end());
  return target_magnitudes(all);
}

struct WindowStatistics {
  std::vector<double> mean, variation;  // per bin: mean amplitude, coefficient of variation
};

// The 100-bin rectangular-window amplitudes of the windows [100 m, 100 m + 1000), first <= m < last.
inline WindowStatistics statistics(const std::vector<double>& x, std::size_t first, std::size_t last) {
  WindowStatistics s{std::vector<double>(dataset::kTargetBins, 0.0), std::vector<double>(dataset::kTargetBins, 0.0)};
  std::vector<double> square(dataset::kTargetBins, 0.0), a(dataset::kTargetBins);
  for (std::size_t m = first; m < last; ++m) {
    signal::amplitude_spectrum(std::span(x).subspan(m * 100, dataset::kWindowSamples), a);
    for (std::size_t k = 0; k < a.size(); ++k) s.mean[k] += a[k], square[k] += a[k] * a[k];
  }
  const double n = double(last - first);
  for (std::size_t k = 0; k < a.size(); ++k) {
    s.mean[k] /= n;
    s.variation[k] = std::sqrt(std::max(0.0, square[k] / n - s.mean[k] * s.mean[k])) / s.mean[k];
  }
  return s;
}

// A noise-like texture's window amplitudes at a steady action: Rayleigh, coefficient of variation
// sqrt(4/pi - 1) per bin.
inline const double kRayleighVariation = std::sqrt(4 / std::numbers::pi - 1);

// The windows' mean amplitudes summed over the bins, over the prediction's. Bins 10 Hz and 1000 Hz
// sit next to DC and to the bins above 1000 Hz, which the frames leave empty: they are left out.
inline double summed_ratio(const WindowStatistics& s, const std::vector<double>& predicted) {
  double p = 0, r = 0;
  for (std::size_t k = 1; k + 1 < predicted.size(); ++k) p += predicted[k], r += s.mean[k];
  return r / p;
}

inline double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
  return v[v.size() / 2];
}

}  // namespace haptex::render::test_windows
