#pragma once
// The signals of each material's sections, as the split assigns them: the test sections the
// evaluation renders and scores, and the training and validation sections the AR refit learns from.
// Evaluation windows are laid on each test section on their own grid (section_grid), so nothing
// depends on how align strided its training windows and no window leaves its section.
#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "dataset/window.hpp"
#include "evaluate/baselines/ar_segments.hpp"
#include "split/split_windows.hpp"

namespace haptex::evaluate {

struct SectionSignals {
  int recording = 0, section = 0;
  std::string source_sha256;                // the recording's @source_sha256 (empty when absent): matches truth.h5
  std::int64_t begin = 0;                   // first sample of the section in its recording
  std::vector<double> accel, force, speed;  // DFT321 acceleration (m/s^2), low-passed force (N) and speed (mm/s)
};

struct MaterialSignals {
  std::string id, name;
  std::vector<SectionSignals> test, training;  // training: the train and validation sections
  std::vector<TrainingPiece> pieces() const;   // views of `training` for the AR refit
};

// Throws haptex::Error (bad_input) naming the dataset and the object when a recording lacks a signal.
std::vector<MaterialSignals> read_section_signals(const split::DatasetSplit& split);

// Offsets (from the section's first sample) of the evaluation windows: t = 0, 100, 200, ... while the
// window's 1000 samples fit (the rule of dataset::window_starts). Empty for short sections.
std::vector<std::size_t> section_grid(std::size_t samples);

// The 20 action values of each grid window (columns), as the model takes them: 5 ms apart up to the
// window's middle (dataset/window.hpp).
Eigen::MatrixXf grid_actions(const SectionSignals& s, const std::vector<std::size_t>& grid);

// The 100-bin amplitude spectra of signal[t - origin, t - origin + 1000) for each grid offset t (rows).
std::vector<std::vector<double>> grid_spectra(const std::vector<double>& signal, const std::vector<std::size_t>& grid,
                                              std::size_t origin = 0);

}  // namespace haptex::evaluate
