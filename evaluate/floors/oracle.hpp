#pragma once
// The oracle: the expected spectrum of each test window under the process that generated the
// recording, where truth.h5 (dataset/truth_file.hpp) says what that was. No predictor can do better
// on average; a model that does beyond its sampling error means the oracle is wrong
// (docs/evaluate.md, "The noise floor").
// - "hatt-model": the generating piecewise AR model along the true, noise-free action with its
//   history (evaluate/baselines/ar_expectation.hpp: closed form where it agrees with Monte Carlo);
// - "synth-material": truth.h5's grid of expected spectra, interpolated at the true action.
// Both add the sensor noise of the three accelerometer axes as DFT321 keeps it.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "evaluate/baselines/ar_expectation.hpp"
#include "evaluate/inputs/section_signals.hpp"
#include "dataset/truth_file.hpp"

namespace haptex::evaluate {

struct MaterialOracle {
  std::string method;  // "closed form", "Monte Carlo" or "truth grid"
  // Per test section (MaterialSignals::test order), per section_grid window: the expected spectrum.
  std::vector<std::vector<std::vector<double>>> spectra;
  // The same process knowing only what the model is given: the recorded action at the window's
  // middle (align/window_table.hpp), held over the window, with the sensor noise (closed form or
  // the grid). How far the oracle lies below it is what the model's input cannot tell.
  std::vector<std::vector<std::vector<double>>> input_spectra;
  std::optional<ArExpectation> ar;  // hatt-model only: both ways and the renderings
};

// nullopt when the truth does not know the material or one of its test sections' recordings (by
// @source_sha256). recorded: per test section, the recording's spectra on section_grid.
// Throws haptex::Error (bad_input) naming truth_path when the truth's action is shorter than a
// section or its model file does not parse.
// Whether the truth knows one of the test sections' recordings (by source SHA-256): a truth.h5 of
// another synth run knows none (review 6: it was compared with the models all the same).
bool truth_knows_any(const dataset::Truth& truth, const std::vector<MaterialSignals>& signals);

std::optional<MaterialOracle> material_oracle(const dataset::Truth& truth, const std::string& truth_path, const MaterialSignals& m,
                                              const std::vector<std::vector<std::vector<double>>>& recorded, std::uint64_t seed);

// Does a predictor beat the oracle beyond sampling error? Per-window distances of each on the same
// windows, paired: the mean difference below -3 standard errors, counting one window in ten as
// independent (neighbouring windows overlap by 90 %). Throws haptex::Error when the sizes differ.
bool beats_oracle(const std::vector<double>& model, const std::vector<double>& oracle);

// Expected amplitude spectrum of a noise-free truth-grid spectrum with white sensor noise of
// `noise_power` (m/s^2)^2 per sample added, in a 1000-sample window: sqrt(a^2 + pi noise_power / N)
// per bin (the Rayleigh mean of the summed power).
void add_sensor_noise(std::vector<double>& amplitude, double noise_power);

// The truth grid's spectrum at one action: bilinear in power over the grid extended by silent
// rows at speed 0 and force 0, held at the grid's edge beyond its maxima.
std::vector<double> grid_power_at(const dataset::TruthGrid& grid, double speed, double force);

}  // namespace haptex::evaluate
