#include "render/noise_frames.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/signal/stft.hpp"
#include "dataset/window.hpp"
#include "render/target_magnitudes.hpp"

namespace haptex::render {
namespace {

using dataset::kWindowSamples;

double mean_magnitude_gain(const std::vector<double>& window) {
  double energy = 0;
  for (double w : window) energy += w * w;
  return 2.0 / std::sqrt(std::numbers::pi * energy);
}

}  // namespace

NoiseFrames::NoiseFrames(std::uint64_t seed)
    : fft_(signal::real_fft<double>(kWindowSamples)),
      window_(signal::hann_periodic(kWindowSamples)),
      noise_(kWindowSamples),
      frame_(kWindowSamples),
      spectrum_(kReconstructionBins),
      unit_gain_(mean_magnitude_gain(window_)),
      random_(seed) {
  fft_.forward(frame_, spectrum_);  // sizes FFTW's per-thread scratch on this thread now
}

std::span<const std::complex<double>> NoiseFrames::next() {
  if (!started_) {
    for (double& x : noise_) x = normal_(random_);
    started_ = true;
  } else {  // the next frame starts 100 samples on
    std::copy(noise_.begin() + kReconstructionHop, noise_.end(), noise_.begin());
    for (auto x = noise_.end() - kReconstructionHop; x != noise_.end(); ++x) *x = normal_(random_);
  }
  for (std::size_t i = 0; i < kWindowSamples; ++i) frame_[i] = window_[i] * noise_[i];
  fft_.forward(frame_, spectrum_);
  return spectrum_;
}

void NoiseFrames::restart() { started_ = false; }

}  // namespace haptex::render
