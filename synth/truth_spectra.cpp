#include "synth/truth_spectra.hpp"

#include <cmath>
#include <numbers>
#include <random>

#include "core/signal/spectrum.hpp"
#include "dataset/window.hpp"

namespace haptex::synth {
namespace {

constexpr std::size_t kSettle = 1000;  // samples for the resonance to forget its start
constexpr std::size_t kWindowsPerStroke = 4;  // consecutive windows along each straight stroke

std::vector<double> linear_grid(double low, double high, int count) {
  std::vector<double> values;
  for (int i = 0; i < count; ++i) values.push_back(low + (high - low) * i / std::max(1, count - 1));
  return values;
}

// Mean amplitude spectrum of straight strokes at one constant speed and force.
void mean_spectrum(const ProbeVibration& probe, double speed, double force, int strokes, std::mt19937_64& rng,
                   double* out) {
  std::uniform_real_distribution<double> unit(0, 1);
  const std::size_t n = kSettle + kWindowsPerStroke * dataset::kWindowSamples;
  std::vector<double> x(n), y(n), f(n, force), spectrum(dataset::kTargetBins);
  std::fill(out, out + dataset::kTargetBins, 0.0);
  for (int s = 0; s < strokes; ++s) {
    const double angle = 2 * std::numbers::pi * unit(rng), x0 = 100 * unit(rng), y0 = 100 * unit(rng);
    for (std::size_t i = 0; i < n; ++i) {
      x[i] = x0 + speed * std::cos(angle) * double(i) / dataset::kSampleRateHz;
      y[i] = y0 + speed * std::sin(angle) * double(i) / dataset::kSampleRateHz;
    }
    const std::vector<double> vibration = probe.along_path(x, y, f, dataset::kSampleRateHz);
    for (std::size_t w = 0; w < kWindowsPerStroke; ++w) {
      signal::amplitude_spectrum(std::span(vibration).subspan(kSettle + w * dataset::kWindowSamples, dataset::kWindowSamples),
                                 spectrum);
      for (std::size_t k = 0; k < spectrum.size(); ++k) out[k] += spectrum[k] / double(strokes * kWindowsPerStroke);
    }
  }
}

}  // namespace

dataset::TruthGrid expected_spectra(const ProbeVibration& probe, const StrokeLimits& limits, std::uint64_t seed,
                           const TruthOptions& options) {
  dataset::TruthGrid grid;
  grid.speeds_mm_s = linear_grid(0.1 * limits.max_speed_mm_s, limits.max_speed_mm_s, options.speeds);
  grid.forces_n = linear_grid(0.1 * limits.max_force_n, limits.max_force_n, options.forces);
  grid.spectra.resize(grid.speeds_mm_s.size() * grid.forces_n.size() * dataset::kTargetBins);
  std::mt19937_64 rng(seed);
  for (std::size_t s = 0; s < grid.speeds_mm_s.size(); ++s)
    for (std::size_t f = 0; f < grid.forces_n.size(); ++f)
      mean_spectrum(probe, grid.speeds_mm_s[s], grid.forces_n[f], options.strokes_per_point, rng,
                    grid.spectra.data() + (s * grid.forces_n.size() + f) * dataset::kTargetBins);
  return grid;
}

}  // namespace haptex::synth
