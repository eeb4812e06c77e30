#include "evaluate/measures/spectral_distance.hpp"

#include <string>

#include "core/error.hpp"
#include "core/signal/spectrum.hpp"
#include "dataset/window.hpp"
#include "evaluate/measures/summary_statistics.hpp"

namespace haptex::evaluate {
namespace {

using dataset::kTargetBins;
using dataset::kWindowSamples;

void check_signals(std::size_t rendered, std::size_t truth) {
  if (rendered != truth)
    throw failure("spectral distance: the rendered signal has " + std::to_string(rendered) +
                  " samples and the true one " + std::to_string(truth) + "; compare signals of the same length");
  if (rendered < kWindowSamples)
    throw failure("spectral distance: the signals have " + std::to_string(rendered) + " samples, shorter than one " +
                  std::to_string(kWindowSamples) + "-sample window");
}

}  // namespace

std::size_t distance_windows(std::size_t n) { return n < kWindowSamples ? 0 : 1 + (n - kWindowSamples) / kDistanceStep; }

std::vector<double> window_distances(std::span<const double> rendered, std::span<const double> truth) {
  check_signals(rendered.size(), truth.size());
  std::vector<double> distances(distance_windows(rendered.size()));
  std::vector<double> rendered_spectrum(kTargetBins), true_spectrum(kTargetBins);
  for (std::size_t w = 0; w < distances.size(); ++w) {
    const std::size_t start = w * kDistanceStep;
    signal::amplitude_spectrum(rendered.subspan(start, kWindowSamples), rendered_spectrum, 1);
    signal::amplitude_spectrum(truth.subspan(start, kWindowSamples), true_spectrum, 1);
    distances[w] = spectrum_distance(rendered_spectrum, true_spectrum);
  }
  return distances;
}

double spectral_distance(std::span<const double> rendered, std::span<const double> truth) {
  return mean(window_distances(rendered, truth));
}

}  // namespace haptex::evaluate
