#pragma once
// The expected amplitude spectrum of a piecewise AR model's vibration along a known action: what
// the model predicts when it is used as a spectrum predictor, like for like with the learned models,
// and, for the generating model itself, the noise floor (docs/evaluate.md, "The noise floor").
//
// Two ways, each checking the other:
// - closed form (core/ar/expected_spectrum.hpp): exact for a stationary action, blind to a filter
//   still ringing after its excitation stopped (HaTT's poles reach radius 0.9986: ~70 ms);
// - Monte Carlo: the model rendered many times along the action from its history, with fresh seeds,
//   and the window spectra averaged.
// expected_ar_spectra keeps the closed form where its window spectra agree with Monte Carlo's within
// 2 % (ArExpectation::gap), and Monte Carlo otherwise.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "core/ar/piecewise_model.hpp"

namespace haptex::evaluate {

// One test section's action for an AR model and the recording's windows on it.
struct ArSection {
  std::vector<double> speed, force;  // mm/s, N: from `lead` samples before the section to its end
  std::size_t lead = 0;              // samples of history before the section's first sample
  std::vector<std::size_t> grid;     // window starts, from the section's first sample
  std::vector<std::vector<double>> recorded;  // the recording's spectra of those windows
};

// History the Monte Carlo renderings start from: 0.3 s, after which the slowest HaTT pole keeps
// 1.5 % of its amplitude. Baselines without a history hold the section's first action that long.
inline constexpr std::size_t kArLeadSamples = 3000;

// The section's recorded action with kArLeadSamples of its first value held before it.
ArSection held_start_section(const std::vector<double>& speed, const std::vector<double>& force, std::vector<std::size_t> grid,
                             std::vector<std::vector<double>> recorded);

struct ArExpectationOptions {
  std::size_t renders = 64;    // Monte Carlo renderings per section; 0: the closed form alone
  std::size_t kept = 10;       // renderings whose spectra are kept as "rendered" (ArExpectation::rendered)
  double noise_power = 0;      // white sensor noise variance per sample added to the vibration, (m/s^2)^2
  double agreement = 0.02;     // closed form used while ArExpectation::gap is at most this
  std::uint64_t seed = 0;
};

inline constexpr double kNoRenders = std::numeric_limits<double>::quiet_NaN();  // renders = 0

struct ArExpectation {
  // Per section, per window: the chosen expected spectra.
  std::vector<std::vector<std::vector<double>>> spectra;
  std::string method;  // "closed form" or "Monte Carlo"
  // Mean distance to the recorded windows over all sections: each way, and the kept renderings'.
  double closed_form = 0, monte_carlo = kNoRenders, rendered = kNoRenders;
  // Mean over the windows of |sum of the closed form's bins / sum of Monte Carlo's - 1|: the test.
  double gap = kNoRenders;
  // Per section, per kept rendering, per window: the spectra of single renderings (realism).
  std::vector<std::vector<std::vector<std::vector<double>>>> rendered_spectra;
  double closed_form_seconds = 0;  // compute time of the closed form (thread CPU)
  std::size_t closed_form_windows = 0;
};

// Throws as core/ar does (a non-finite action).
ArExpectation expected_ar_spectra(const ar::PiecewiseArModel& model, const std::vector<ArSection>& sections,
                                  const ArExpectationOptions& options);

}  // namespace haptex::evaluate
