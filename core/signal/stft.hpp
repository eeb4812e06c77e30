#pragma once
// Short-time Fourier transform with a periodic Hann window and its least-squares inverse
// (Griffin & Lim 1984: weighted overlap-add divided by the summed squared window).
#include <complex>
#include <span>
#include <vector>

namespace haptex::signal {

struct StftConfig {
  std::size_t window = 1000;
  std::size_t hop = 100;
  // true: frame m is centred on sample m*hop (window/2 zeros padded at both ends, as librosa's
  // center=True); false: frame m covers samples [m*hop, m*hop + window).
  bool centered = true;
};

// frames x (window/2 + 1) bins, row-major.
struct Spectrogram {
  std::size_t frames = 0, bins = 0;
  std::vector<std::complex<double>> values;
  std::complex<double>& at(std::size_t f, std::size_t k) { return values[f * bins + k]; }
  const std::complex<double>& at(std::size_t f, std::size_t k) const { return values[f * bins + k]; }
};

std::vector<double> hann_periodic(std::size_t n);  // scipy.signal.get_window('hann', n)

// Frame count: centered, 1 + ceil(n / hop); not centered, 1 + (n - window) / hop (n >= window).
std::size_t stft_frames(std::size_t n, const StftConfig& config);
Spectrogram stft(std::span<const double> x, const StftConfig& config);
// Least-squares signal of length n whose STFT is closest to S; samples no window covers are 0.
std::vector<double> istft(const Spectrogram& S, std::size_t n, const StftConfig& config);

}  // namespace haptex::signal
