#include "render/target_magnitudes.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "dataset/window.hpp"

namespace haptex::render {
namespace {

using dataset::kTargetBins;
using dataset::kWindowSamples;

template <typename T>
void convert_frame(std::span<const T> amplitudes, std::span<double> out) {
  if (amplitudes.size() != kTargetBins || out.size() != kReconstructionBins)
    throw failure("target magnitudes: a frame has " + std::to_string(amplitudes.size()) + " amplitudes and " +
                  std::to_string(out.size()) + " output bins; expected " + std::to_string(kTargetBins) + " and " +
                  std::to_string(kReconstructionBins));
  const double scale = hann_rms_gain() * static_cast<double>(kWindowSamples) / 2.0;
  std::fill(out.begin(), out.end(), 0.0);
  for (std::size_t k = 0; k < kTargetBins; ++k) {
    const double a = static_cast<double>(amplitudes[k]);
    if (!(a >= 0.0 && std::isfinite(a)))
      throw failure("target magnitudes: amplitude " + std::to_string(k + 1) + " is " + std::to_string(a) +
                    "; amplitudes must be finite and non-negative");
    out[k + 1] = scale * a;
  }
}

template <typename T>
MagnitudeFrames convert_frames(std::span<const T> amplitudes) {
  if (amplitudes.size() % kTargetBins != 0)
    throw failure("target magnitudes: " + std::to_string(amplitudes.size()) + " amplitudes are not whole frames of " +
                  std::to_string(kTargetBins));
  MagnitudeFrames out;
  out.frames = amplitudes.size() / kTargetBins;
  out.bins = kReconstructionBins;
  out.values.resize(out.frames * out.bins);
  for (std::size_t f = 0; f < out.frames; ++f)
    convert_frame(amplitudes.subspan(f * kTargetBins, kTargetBins), out.row(f));
  return out;
}

}  // namespace

std::size_t covered_samples(std::size_t frames) {
  return frames == 0 ? 0 : (frames - 1) * kReconstructionHop + kWindowSamples;
}

void check_magnitude_frame(std::span<const double> magnitudes, const char* who) {
  if (magnitudes.size() != kReconstructionBins)
    throw failure(std::string(who) + ": a frame has " + std::to_string(magnitudes.size()) + " magnitudes, expected " +
                  std::to_string(kReconstructionBins));
  for (std::size_t k = 0; k < magnitudes.size(); ++k)
    if (!(magnitudes[k] >= 0.0 && std::isfinite(magnitudes[k])))
      throw failure(std::string(who) + ": magnitude " + std::to_string(k) + " is " + std::to_string(magnitudes[k]) +
                    "; magnitudes must be finite and non-negative");
}

double synthesis_gain(std::span<const double> window, std::size_t n, std::size_t frames) {
  // Frames m with m * hop <= n < m * hop + window, and m < frames.
  const std::size_t last = std::min(n / kReconstructionHop, frames == 0 ? 0 : frames - 1);
  const std::size_t first = n < window.size() ? 0 : (n - window.size()) / kReconstructionHop + 1;
  double sum = 0.0;
  for (std::size_t m = first; m <= last && frames > 0; ++m) {
    const double w = window[n - m * kReconstructionHop];
    sum += w * w;
  }
  return 1.0 / std::max(sum, kSynthesisWeightFloor);
}

// Over a whole period (periodic window), mean((1/2 - cos/2)^2) = 1/4 + 1/8: the cross term averages out.
double hann_rms_gain() { return std::sqrt(3.0 / 8.0); }

void target_magnitude_frame(std::span<const double> amplitudes, std::span<double> out) {
  convert_frame(amplitudes, out);
}
void target_magnitude_frame(std::span<const float> amplitudes, std::span<double> out) {
  convert_frame(amplitudes, out);
}

MagnitudeFrames target_magnitudes(std::span<const double> amplitudes) { return convert_frames(amplitudes); }
MagnitudeFrames target_magnitudes(std::span<const float> amplitudes) { return convert_frames(amplitudes); }

}  // namespace haptex::render
