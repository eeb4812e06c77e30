#include "core/signal/spectrum.hpp"

#include <cmath>
#include <complex>
#include <string>

#include "core/error.hpp"
#include "core/signal/fft.hpp"

namespace haptex::signal {
namespace {

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

}  // namespace

void amplitude_spectrum(std::span<const double> window, std::span<double> out, std::size_t first_bin) {
  const std::size_t n = window.size();
  if (n == 0) throw failure("amplitude spectrum: the window is empty");
  const auto& fft = real_fft<double>(n);
  if (first_bin + out.size() > fft.bins())
    throw failure("amplitude spectrum: bins " + std::to_string(first_bin) + ".." +
                  std::to_string(first_bin + out.size() - 1) + " requested, a " + std::to_string(n) +
                  "-sample window has bins 0.." + std::to_string(fft.bins() - 1));
  // Called once per training window: a per-thread buffer that only grows keeps it allocation-free.
  thread_local std::vector<std::complex<double>> spectrum;
  if (spectrum.size() < fft.bins()) spectrum.resize(fft.bins());
  const std::span<std::complex<double>> X(spectrum.data(), fft.bins());
  fft.forward(window, X);
  const double scale = 2.0 / static_cast<double>(n);
  for (std::size_t k = 0; k < out.size(); ++k) out[k] = scale * std::abs(X[first_bin + k]);
}

std::vector<double> amplitude_spectrum(std::span<const double> window, std::size_t bins) {
  std::vector<double> out(bins);
  amplitude_spectrum(window, out, 1);
  return out;
}

double spectrum_distance(std::span<const double> a, std::span<const double> b) { return euclidean(a, b); }
double spectrum_distance(std::span<const float> a, std::span<const float> b) { return euclidean(a, b); }

}  // namespace haptex::signal
