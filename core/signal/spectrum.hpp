#pragma once
// The model's target: the single-sided amplitude spectrum of one window (docs/align.md, Windows),
// and the distance of two such spectra.
#include <cstddef>
#include <span>
#include <vector>

namespace haptex::signal {

// 2 |X_k| / N for k = first_bin .. first_bin + bins - 1, rectangular window, N = window.size().
// Writes into out (size bins); no allocation after the first call per window size.
void amplitude_spectrum(std::span<const double> window, std::span<double> out, std::size_t first_bin = 1);
// Bins 1..bins of the window (the model's target: dataset/window.hpp gives its sizes).
std::vector<double> amplitude_spectrum(std::span<const double> window, std::size_t bins);

// Euclidean distance of two amplitude spectra of the same, non-zero length: the evaluation's loss
// per window (evaluate/measures/spectral_distance.hpp), which haptex render also reports, so it lives below
// both. Float spectra are summed in double. Throws haptex::Error when the lengths differ or are zero.
double spectrum_distance(std::span<const double> a, std::span<const double> b);
double spectrum_distance(std::span<const float> a, std::span<const float> b);

}  // namespace haptex::signal
