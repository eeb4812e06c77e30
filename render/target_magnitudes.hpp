#pragma once
// The frames phase reconstruction works on, and the model's spectra converted to them.
//
// The model predicts, every 100 samples, the 100-bin amplitude spectrum (2|X_k|/N, rectangular
// window, bins 1..100 = 10..1000 Hz) of the 1000 samples starting there. Reconstruction uses those
// windows as STFT frames: periodic Hann, window 1000, hop 100, not centred (frame m covers
// [100 m, 100 m + 1000)), 501 bins of which DC and bins above 100 are zero.
#include <cstddef>
#include <span>
#include <vector>

#include "core/signal/spectrum.hpp"
#include "core/signal/stft.hpp"
#include "dataset/window.hpp"

namespace haptex::render {

inline constexpr std::size_t kReconstructionHop = dataset::kGridStride;  // one frame per predicted window
inline constexpr std::size_t kReconstructionBins = dataset::kWindowSamples / 2 + 1;  // 501
inline constexpr signal::StftConfig kReconstructionStft{dataset::kWindowSamples, kReconstructionHop, false};

// Non-negative STFT magnitudes, frames x bins, row-major.
struct MagnitudeFrames {
  std::size_t frames = 0, bins = 0;
  std::vector<double> values;

  std::span<const double> row(std::size_t f) const { return std::span(values).subspan(f * bins, bins); }
  std::span<double> row(std::size_t f) { return std::span(values).subspan(f * bins, bins); }
};

// Samples the frames cover: (frames - 1) * 100 + 1000; 0 for no frames.
std::size_t covered_samples(std::size_t frames);

// Overlap-add normalisation: the least-squares inverse of the frames divides the sum of the
// window-weighted frames at sample n by the sum of w^2 over the frames 0..frames-1 that cover n.
// In the first and last 900 samples that sum falls towards w[1]^2 ~ 1e-5, and an inconsistent
// frame (one whose magnitudes no signal has) would come out amplified 1e5-fold; so the divisor is
// at least kSynthesisWeightFloor, a tenth of the steady-state sum 3.75, and the edges fade instead.
// Returns 1 / max(sum, floor); window is hann_periodic(1000).
inline constexpr double kSynthesisWeightFloor = 0.375;
double synthesis_gain(std::span<const double> window, std::size_t n, std::size_t frames);

// The factor from a rectangular-window DFT magnitude to the Hann one: sqrt(mean(w^2)) = sqrt(3/8).
// Texture vibration is noise-like (AR-filtered noise in the HaTT models): its energy spreads over
// each bin's neighbourhood, so a window scales the expected |X_k|^2 by sum(w^2), not by the
// coherent gain (sum w)^2 / N that holds only for a sine centred on a bin (0.5 for Hann, 18% lower).
double hann_rms_gain();

// One frame: 100 amplitudes a_k (bins 1..100) -> 501 magnitudes |X_k| = hann_rms_gain() * N/2 * a_k,
// zero at DC and above bin 100. Throws haptex::Error for other sizes or a negative or non-finite
// amplitude. Does not allocate.
void target_magnitude_frame(std::span<const double> amplitudes, std::span<double> out);
void target_magnitude_frame(std::span<const float> amplitudes, std::span<double> out);

// Throws haptex::Error, naming `who`, unless `magnitudes` is one frame of 501 finite, non-negative values.
void check_magnitude_frame(std::span<const double> magnitudes, const char* who);

// The whole signal of a streaming synthesis (OnlineReconstruction, ShapedNoise: push(frame) and flush()
// returning samples): every frame pushed, then flushed, cut or padded with zeros to `length`.
template <typename Stream>
std::vector<double> stream_frames(Stream& stream, const MagnitudeFrames& s, std::size_t length) {
  std::vector<double> out;
  out.reserve(covered_samples(s.frames));
  for (std::size_t m = 0; m < s.frames; ++m) {
    const std::span<const double> samples = stream.push(s.row(m));
    out.insert(out.end(), samples.begin(), samples.end());
  }
  const std::span<const double> tail = stream.flush();
  out.insert(out.end(), tail.begin(), tail.end());
  out.resize(length, 0.0);
  return out;
}

// frames x 100 amplitudes (row-major) -> frames x 501 magnitudes. Throws haptex::Error when the
// size is not a multiple of 100.
MagnitudeFrames target_magnitudes(std::span<const double> amplitudes);
MagnitudeFrames target_magnitudes(std::span<const float> amplitudes);

}  // namespace haptex::render
