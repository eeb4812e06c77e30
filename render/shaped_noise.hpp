#pragma once
// Vibration from predicted spectra without phase reconstruction: white Gaussian noise shaped frame by
// frame to the predicted magnitudes (weighted overlap-add on the reconstruction frames of
// render/target_magnitudes.hpp), as HaTT's models shape white noise with an AR filter.
//
// Why: texture vibration is noise; it has no phase worth recovering. Griffin-Lim finds a signal whose
// every window has the smooth expected spectrum, which no surface plays, so it sounds too steady and
// loses level where frames disagree. Shaped noise keeps each frame's expected magnitudes and lets each
// window's amplitudes scatter around them as a recording's do (Rayleigh; docs/evaluate.md, "Realism of
// rendered signals"). The price is in the spectral distance: a rendering that varies like the surface
// lies sqrt(2) times the oracle's distance from a recording even when its spectra are perfect, where a
// steady one can approach the oracle.
//
// Frame m (samples [100 m, 100 m + 1000)) is the Hann-windowed noise of its span, transformed, each bin
// scaled so that its mean magnitude is the target's (a Rayleigh magnitude's mean is sqrt(pi)/2 of its
// RMS), transformed back, windowed again and overlap-added; the sum is divided by the frames' summed
// squared windows (synthesis_gain), as Griffin-Lim's inverse does. One noise stream runs through all
// frames, so overlapping frames add coherently and the level holds. Causal and without look-ahead:
// pushing frame m completes samples [100 m, 100 m + 100).
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/signal/fft.hpp"
#include "render/noise_frames.hpp"
#include "render/target_magnitudes.hpp"

namespace haptex::render {

// For a haptic loop: construct once, push one magnitude frame every 100 samples, play what push
// returns. Allocation-free after construction (as OnlineReconstruction: FFTW's per-thread scratch
// is sized on a thread's first push). The same seed gives the same signal.
struct ShapedNoiseOptions {
  std::uint64_t seed = 0;
};

class ShapedNoise {
 public:
  explicit ShapedNoise(const ShapedNoiseOptions& options = {});

  // Feeds frame m's 501 Hann-STFT magnitudes; returns samples [100 m, 100 m + 100), valid until the
  // next call. Throws haptex::Error for a wrong size or a negative or non-finite magnitude.
  std::span<const double> push(std::span<const double> magnitudes);
  // Ends the stream: the last frame's remaining 900 samples (none before any push). Then a new
  // stream starts, continuing the noise.
  std::span<const double> flush();

 private:
  const signal::RealFft<double>& fft_;
  NoiseFrames noise_;
  std::vector<double> frame_, sum_, output_;
  std::vector<std::complex<double>> spectrum_;
  std::size_t frames_ = 0;
};

// The whole signal of `length` samples for frames x 501 magnitudes: every frame pushed, then
// flushed; a longer request is padded with zeros, a shorter one cut. Throws as ShapedNoise::push.
std::vector<double> shaped_noise(const MagnitudeFrames& s, std::size_t length, const ShapedNoiseOptions& options = {});

}  // namespace haptex::render
