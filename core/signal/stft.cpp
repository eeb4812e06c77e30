#include "core/signal/stft.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "core/error.hpp"
#include "core/signal/fft.hpp"

namespace haptex::signal {
namespace {

void check_config(const StftConfig& config) {
  if (config.window == 0 || config.hop == 0)
    throw failure("STFT: window (" + std::to_string(config.window) + ") and hop (" + std::to_string(config.hop) +
                  ") must both be at least 1 sample");
}

// Signal index of sample j of frame m; negative or >= n means outside the signal (zero).
std::ptrdiff_t sample_index(std::size_t m, std::size_t j, const StftConfig& config) {
  const std::size_t offset = config.centered ? config.window / 2 : 0;
  return static_cast<std::ptrdiff_t>(m * config.hop + j) - static_cast<std::ptrdiff_t>(offset);
}

bool inside(std::ptrdiff_t index, std::size_t n) { return index >= 0 && static_cast<std::size_t>(index) < n; }

}  // namespace

std::vector<double> hann_periodic(std::size_t n) {
  if (n <= 1) return std::vector<double>(n, 1.0);  // scipy returns [1.] for one point
  std::vector<double> w(n);
  for (std::size_t i = 0; i < n; ++i)
    w[i] = 0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n));
  return w;
}

std::size_t stft_frames(std::size_t n, const StftConfig& config) {
  check_config(config);
  if (config.centered) return 1 + (n + config.hop - 1) / config.hop;
  return n < config.window ? 0 : 1 + (n - config.window) / config.hop;
}

Spectrogram stft(std::span<const double> x, const StftConfig& config) {
  check_config(config);
  const std::size_t n = x.size();
  const auto& fft = real_fft<double>(config.window);
  const auto w = hann_periodic(config.window);
  Spectrogram S;
  S.frames = stft_frames(n, config);
  S.bins = fft.bins();
  S.values.resize(S.frames * S.bins);
  std::vector<double> frame(config.window);
  for (std::size_t m = 0; m < S.frames; ++m) {
    for (std::size_t j = 0; j < config.window; ++j) {
      const auto index = sample_index(m, j, config);
      frame[j] = inside(index, n) ? w[j] * x[static_cast<std::size_t>(index)] : 0.0;
    }
    fft.forward(frame, std::span(S.values).subspan(m * S.bins, S.bins));
  }
  return S;
}

std::vector<double> istft(const Spectrogram& S, std::size_t n, const StftConfig& config) {
  check_config(config);
  const auto& fft = real_fft<double>(config.window);
  if (S.bins != fft.bins() || S.values.size() != S.frames * S.bins)
    throw failure("inverse STFT: the spectrogram has " + std::to_string(S.frames) + " frames x " +
                  std::to_string(S.bins) + " bins (" + std::to_string(S.values.size()) + " values); a " +
                  std::to_string(config.window) + "-sample window needs " + std::to_string(fft.bins()) + " bins");
  const auto w = hann_periodic(config.window);
  // Griffin & Lim: the least-squares signal is the window-weighted overlap-add of the frames
  // divided by the summed squared window at each sample.
  std::vector<double> sum(n, 0.0), weight(n, 0.0), frame(config.window);
  for (std::size_t m = 0; m < S.frames; ++m) {
    fft.inverse(std::span(S.values).subspan(m * S.bins, S.bins), frame);
    for (std::size_t j = 0; j < config.window; ++j) {
      const auto index = sample_index(m, j, config);
      if (!inside(index, n)) continue;
      sum[static_cast<std::size_t>(index)] += w[j] * frame[j];
      weight[static_cast<std::size_t>(index)] += w[j] * w[j];
    }
  }
  for (std::size_t i = 0; i < n; ++i) sum[i] = weight[i] > 0.0 ? sum[i] / weight[i] : 0.0;
  return sum;
}

}  // namespace haptex::signal
