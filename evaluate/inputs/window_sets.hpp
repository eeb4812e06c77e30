#pragma once
// Evaluation windows of sections with their spectra and where they lie in action space, and what a
// material's training windows predict without any model: the mean training spectrum (the best
// action-blind predictor) and the empirical noise floor of data without a known generator
// (docs/evaluate.md, "The noise floor").
#include <cstddef>
#include <vector>

#include "evaluate/inputs/section_signals.hpp"

namespace haptex::evaluate {

// Mean low-passed speed (mm/s) and force (N) over a window's 1000 target samples.
struct MeanAction {
  double speed = 0, force = 0;
};

struct WindowSet {
  std::vector<std::vector<double>> spectra;  // 100-bin amplitude spectra, one per window
  std::vector<MeanAction> actions;           // the same windows' mean actions
  void append(const WindowSet& other);
};

// The windows of section_grid(s.accel.size()) on one section.
WindowSet section_windows(const SectionSignals& s);
// Their action points alone (no spectra computed).
std::vector<MeanAction> section_actions(const SectionSignals& s);

// Every training (train and validation) section's windows of a material.
WindowSet training_windows(const MaterialSignals& m);

// The mean of the spectra; zeros for an empty set.
std::vector<double> mean_spectrum(const WindowSet& w);

// For each query, the mean spectrum of the k training windows nearest in action space (speed and
// force each divided by its spread over the training windows): an estimate of the best possible
// prediction where the generating process is unknown. Ties keep the earlier window. Throws
// haptex::Error when training is empty or k is 0.
std::vector<std::vector<double>> nearest_action_spectra(const WindowSet& training, const std::vector<MeanAction>& queries,
                                                        std::size_t k);

inline constexpr std::size_t kNearestWindows = 32;  // ~9 % sampling error per bin, a narrow slice of actions

}  // namespace haptex::evaluate
