#include "render/shaped_noise.hpp"

#include <algorithm>

#include "core/signal/stft.hpp"
#include "dataset/window.hpp"

namespace haptex::render {
namespace {

using dataset::kWindowSamples;

}  // namespace

ShapedNoise::ShapedNoise(const ShapedNoiseOptions& options)
    : fft_(signal::real_fft<double>(kWindowSamples)),
      noise_(options.seed),
      frame_(kWindowSamples),
      sum_(kWindowSamples, 0.0),
      output_(kWindowSamples - kReconstructionHop),
      spectrum_(kReconstructionBins) {
  fft_.inverse(spectrum_, frame_);  // sizes FFTW's per-thread scratch on this thread now
}

std::span<const double> ShapedNoise::push(std::span<const double> magnitudes) {
  check_magnitude_frame(magnitudes, "shaped noise");
  if (frames_ > 0) {  // the next frame starts 100 samples on: advance the running sum
    std::copy(sum_.begin() + kReconstructionHop, sum_.end(), sum_.begin());
    std::fill(sum_.end() - kReconstructionHop, sum_.end(), 0.0);
  }
  const std::span<const std::complex<double>> noise = noise_.next();
  const double gain = noise_.unit_gain();
  for (std::size_t k = 0; k < kReconstructionBins; ++k) spectrum_[k] = noise[k] * (gain * magnitudes[k]);
  fft_.inverse(spectrum_, frame_);
  const std::span<const double> window = noise_.window();
  for (std::size_t i = 0; i < kWindowSamples; ++i) sum_[i] += window[i] * frame_[i];
  const std::size_t first = frames_ * kReconstructionHop;
  ++frames_;
  for (std::size_t i = 0; i < kReconstructionHop; ++i) output_[i] = sum_[i] * synthesis_gain(window, first + i, frames_);
  return std::span<const double>(output_).first(kReconstructionHop);
}

std::span<const double> ShapedNoise::flush() {
  if (frames_ == 0) return {};
  const std::size_t first = frames_ * kReconstructionHop;  // the last frame's samples not yet returned
  for (std::size_t i = 0; i < output_.size(); ++i) output_[i] = sum_[kReconstructionHop + i] * synthesis_gain(noise_.window(), first + i, frames_);
  std::fill(sum_.begin(), sum_.end(), 0.0);
  noise_.restart();  // the next stream's first frame: fresh noise
  frames_ = 0;
  return output_;
}

std::vector<double> shaped_noise(const MagnitudeFrames& s, std::size_t length, const ShapedNoiseOptions& options) {
  ShapedNoise noise(options);
  return stream_frames(noise, s, length);
}

}  // namespace haptex::render
