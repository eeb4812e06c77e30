#pragma once
// The expected amplitude spectrum (signal::amplitude_spectrum's 2|X_k|/N of a rectangular window)
// that a HaTT piecewise AR model produces along a known speed/force trajectory, in closed form:
// the evaluation compares spectra against this mean instead of against one noisy rendering.
// Valid where the action changes slowly against the filter's memory (the renderer re-blends at
// every sample; here the window's autocorrelation is the average over blends at update samples).
#include <cstddef>
#include <span>
#include <vector>

#include "core/ar/piecewise_model.hpp"

namespace haptex::ar {

// Stationary autocorrelation r[0..lags-1] of 1/A(z), a = [1, a1, ..., ap], driven by white noise of
// the given variance: exact from the coefficients (step-down to reflection coefficients, Levinson
// up-recursion, then the Yule-Walker recursion), O(p^2 + lags p). A zero variance gives zeros.
// Throws haptex::Error when a[0] != 1, a value is not finite, the variance is negative, or the
// filter is not strictly stable (a reflection coefficient with |k| >= 1).
std::vector<double> ar_autocorrelation(std::span<const double> a, double variance, std::size_t lags);

// E|X_k|^2 of the N-sample rectangular-window DFT of a process with autocorrelation r (N = r.size()),
// at bins first_bin .. first_bin + out.size() - 1: N r[0] + 2 sum_{m=1}^{N-1} (N - m) r[m] cos(2 pi k m / N).
// Throws haptex::Error for an empty r or bins past N/2.
void windowed_power(std::span<const double> r, std::span<double> out, std::size_t first_bin = 1);

struct ExpectedSpectrumOptions {
  std::size_t window = 1000;  // samples per window (N)
  std::size_t bins = 100;     // bins 1..bins, all below N/2
  std::size_t update = 10;    // blend every `update` samples, at t + update/2, t + update/2 + update, ...
  double noise_power = 0.0;   // variance (m/s^2)^2 of white sensor noise added to every sample
};

// One expected amplitude spectrum (options.bins values, m/s^2) per window start, the window being
// [start, start + window): the blended models' autocorrelations are averaged over the window, noise
// is added, and each bin is taken as Rayleigh: (2/N) sqrt(pi/4 E|X_k|^2). speed (mm/s) and force (N)
// hold one value per sample. Each update's autocorrelation is computed once per call, so windows that
// overlap (as the evaluation's, 90 %) share them. Throws haptex::Error when the lengths differ, a
// window leaves the trajectory, speed or force inside a window is not finite, or the options are
// out of range.
std::vector<std::vector<double>> expected_window_spectra(const PiecewiseArModel& model, std::span<const double> speed,
                                                         std::span<const double> force,
                                                         std::span<const std::size_t> starts,
                                                         const ExpectedSpectrumOptions& options = {});

}  // namespace haptex::ar
