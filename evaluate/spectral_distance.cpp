#include "evaluate/spectral_distance.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "core/signal/spectrum.hpp"
#include "evaluate/summary_statistics.hpp"

namespace haptex::evaluate {
namespace {

using signal::kSpectrumBins;
using signal::kWindowSamples;

template <typename T>
double euclidean(std::span<const T> a, std::span<const T> b) {
  if (a.size() != b.size() || a.empty())
    throw failure("spectral distance: the spectra have " + std::to_string(a.size()) + " and " +
                  std::to_string(b.size()) + " bins; they must have the same, non-zero number");
  double sum = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    const double d = static_cast<double>(a[k]) - static_cast<double>(b[k]);
    sum += d * d;
  }
  return std::sqrt(sum);
}

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

double spectrum_distance(std::span<const double> a, std::span<const double> b) { return euclidean(a, b); }
double spectrum_distance(std::span<const float> a, std::span<const float> b) { return euclidean(a, b); }

std::vector<double> window_distances(std::span<const double> rendered, std::span<const double> truth) {
  check_signals(rendered.size(), truth.size());
  std::vector<double> distances(distance_windows(rendered.size()));
  std::vector<double> rendered_spectrum(kSpectrumBins), true_spectrum(kSpectrumBins);
  for (std::size_t w = 0; w < distances.size(); ++w) {
    const std::size_t start = w * kDistanceStep;
    signal::amplitude_spectrum(rendered.subspan(start, kWindowSamples), rendered_spectrum, 1);
    signal::amplitude_spectrum(truth.subspan(start, kWindowSamples), true_spectrum, 1);
    distances[w] = euclidean<double>(rendered_spectrum, true_spectrum);
  }
  return distances;
}

double spectral_distance(std::span<const double> rendered, std::span<const double> truth) {
  return mean(window_distances(rendered, truth));
}

}  // namespace haptex::evaluate
