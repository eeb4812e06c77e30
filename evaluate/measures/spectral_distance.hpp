#pragma once
// The evaluation loss (docs/evaluate.md, Spectral distance): slide a 1000-sample window with step 100 over a
// rendered (or predicted) signal and the true one; per window, the Euclidean distance of the two
// 100-bin amplitude spectra (2|X_k|/N, bins 1..100, rectangular window); a segment's loss is the
// mean over its windows.
#include <cstddef>
#include <span>
#include <vector>

#include "core/signal/spectrum.hpp"
#include "dataset/window.hpp"

namespace haptex::evaluate {

inline constexpr std::size_t kDistanceStep = dataset::kGridStride;  // samples between window starts

// Number of windows in n samples: 1 + (n - 1000) / 100 (a tail shorter than a step is not used).
std::size_t distance_windows(std::size_t n);

// Euclidean distance of two amplitude spectra (core/signal/spectrum.hpp): the spectral-domain
// case, where the model's predicted spectra are compared to the dataset's targets directly.
using signal::spectrum_distance;

// One distance per window, window w covering samples [100 w, 100 w + 1000) of both signals.
// Throws haptex::Error when the lengths differ or are shorter than one window (1000 samples).
std::vector<double> window_distances(std::span<const double> rendered, std::span<const double> truth);

// The segment's loss: the mean of window_distances.
double spectral_distance(std::span<const double> rendered, std::span<const double> truth);

}  // namespace haptex::evaluate
