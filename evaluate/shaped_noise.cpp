#include "evaluate/shaped_noise.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/signal/stft.hpp"

namespace haptex::evaluate {
namespace {

using signal::kWindowSamples;
constexpr std::size_t kHop = kReconstructionHop;

// Unit-variance white noise under the Hann window has E|X_k|^2 = sum(w^2); a Rayleigh magnitude's
// mean is sqrt(pi)/2 of its RMS. So the bin gain that gives mean magnitude s_k is s_k times this.
double noise_gain(const std::vector<double>& window) {
  double energy = 0;
  for (double w : window) energy += w * w;
  return 2.0 / std::sqrt(std::numbers::pi * energy);
}

}  // namespace

ShapedNoise::ShapedNoise(const ShapedNoiseOptions& options)
    : fft_(signal::real_fft<double>(kWindowSamples)),
      window_(signal::hann_periodic(kWindowSamples)),
      noise_(kWindowSamples),
      frame_(kWindowSamples),
      sum_(kWindowSamples, 0.0),
      output_(kWindowSamples - kHop),
      spectrum_(kReconstructionBins),
      gain_(noise_gain(window_)),
      random_(options.seed) {
  for (double& x : noise_) x = normal_(random_);
  fft_.inverse(spectrum_, frame_);  // sizes FFTW's per-thread scratch on this thread now
}

std::span<const double> ShapedNoise::push(std::span<const double> magnitudes) {
  check_magnitude_frame(magnitudes, "shaped noise");
  if (frames_ > 0) {  // the next frame starts 100 samples on: advance the noise and the running sum
    std::copy(noise_.begin() + kHop, noise_.end(), noise_.begin());
    for (auto x = noise_.end() - kHop; x != noise_.end(); ++x) *x = normal_(random_);
    std::copy(sum_.begin() + kHop, sum_.end(), sum_.begin());
    std::fill(sum_.end() - kHop, sum_.end(), 0.0);
  }
  for (std::size_t i = 0; i < kWindowSamples; ++i) frame_[i] = window_[i] * noise_[i];
  fft_.forward(frame_, spectrum_);
  for (std::size_t k = 0; k < kReconstructionBins; ++k) spectrum_[k] *= gain_ * magnitudes[k];
  fft_.inverse(spectrum_, frame_);
  for (std::size_t i = 0; i < kWindowSamples; ++i) sum_[i] += window_[i] * frame_[i];
  const std::size_t first = frames_ * kHop;
  ++frames_;
  for (std::size_t i = 0; i < kHop; ++i) output_[i] = sum_[i] * synthesis_gain(window_, first + i, frames_);
  return std::span<const double>(output_).first(kHop);
}

std::span<const double> ShapedNoise::flush() {
  if (frames_ == 0) return {};
  const std::size_t first = frames_ * kHop;  // the last frame's samples not yet returned
  for (std::size_t i = 0; i < output_.size(); ++i) output_[i] = sum_[kHop + i] * synthesis_gain(window_, first + i, frames_);
  std::fill(sum_.begin(), sum_.end(), 0.0);
  for (double& x : noise_) x = normal_(random_);  // the next stream's first frame: fresh noise
  frames_ = 0;
  return output_;
}

std::vector<double> shaped_noise(const MagnitudeFrames& s, std::size_t length, const ShapedNoiseOptions& options) {
  ShapedNoise noise(options);
  return stream_frames(noise, s, length);
}

}  // namespace haptex::evaluate
