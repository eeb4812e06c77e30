#pragma once
// The model's target: the single-sided amplitude spectrum of one window (DESIGN.md section 3).
#include <span>
#include <vector>

namespace haptex::signal {

inline constexpr std::size_t kWindowSamples = 1000;  // 100 ms at 10 kHz
inline constexpr std::size_t kSpectrumBins = 100;    // 10 Hz .. 1000 Hz

// 2 |X_k| / N for k = first_bin .. first_bin + bins - 1, rectangular window, N = window.size().
// Writes into out (size bins); no allocation after the first call per window size.
void amplitude_spectrum(std::span<const double> window, std::span<double> out, std::size_t first_bin = 1);
std::vector<double> amplitude_spectrum(std::span<const double> window);  // bins 1..100 of a 1000-sample window

}  // namespace haptex::signal
