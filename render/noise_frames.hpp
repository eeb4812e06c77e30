#pragma once
// White Gaussian noise seen through the reconstruction frames (render/target_magnitudes.hpp):
// frame m is the Hann-windowed noise of samples [100 m, 100 m + 1000), transformed. One stream
// runs through the frames, so neighbouring frames share 90 % of their noise as a recording's
// windows share their samples: the frames' magnitudes scatter (Rayleigh) and drift from frame to
// frame the way a noise-like texture's window spectra do.
//
// Two users: shaped noise (render/shaped_noise.hpp) scales each frame's bins to the prediction
// and plays the noise itself; RTISI-LA with scatter (render/online_reconstruction.hpp) takes only
// each bin's relative magnitude, to draw the frame's targets around the prediction before finding
// a phase for them (docs/evaluate.md, "Realism").
#include <complex>
#include <cstdint>
#include <random>
#include <span>
#include <vector>

#include "core/signal/fft.hpp"

namespace haptex::render {

class NoiseFrames {
 public:
  explicit NoiseFrames(std::uint64_t seed);

  // The next frame's 501 bins; valid until the next call. Allocation-free.
  std::span<const std::complex<double>> next();
  // The next call starts a new stream on fresh noise (its frame 0).
  void restart();

  // The factor from a bin of these frames to one of mean magnitude 1: a unit-variance noise under
  // the Hann window has E|X_k|^2 = sum(w^2), and a Rayleigh magnitude's mean is sqrt(pi)/2 of its RMS.
  double unit_gain() const { return unit_gain_; }
  std::span<const double> window() const { return window_; }

 private:
  const signal::RealFft<double>& fft_;
  std::vector<double> window_, noise_, frame_;
  std::vector<std::complex<double>> spectrum_;
  double unit_gain_;
  std::mt19937_64 random_;
  std::normal_distribution<double> normal_;
  bool started_ = false;
};

}  // namespace haptex::render
