#pragma once
// The evaluation's grid as a table (docs/windows.md): every window `haptex evaluate` scores, in the
// order it scores them, with the action the model takes and the recorded spectrum it is scored
// against, so a model trained outside haptex can be scored on exactly these windows. Built from the
// evaluation's own section signals and grid (evaluate/inputs/section_signals.hpp), never re-derived.
#include <cstdint>
#include <string>
#include <vector>

#include "dataset/window_table.hpp"
#include "evaluate/inputs/section_signals.hpp"
#include "split/split_windows.hpp"

namespace haptex::evaluate {

struct EvaluationGrid {
  // material (index into materials: the split's material ids), recording, start (sample of the
  // recording), action and target (float32, as the dataset's windows), stride 100.
  dataset::WindowTable windows;
  std::vector<std::int32_t> section;  // the test section of the recording each window lies in
  std::vector<std::int32_t> press;    // the material's test press (/materials/{material}/presses/{press})
  std::string dataset_sha256, split_sha256;
};

// The grid of every material's test sections as run_evaluation lays it: materials in the split's
// order, then their test sections as read_section_signals lists them, windows by start.
EvaluationGrid evaluation_grid(const split::DatasetSplit& split, const std::vector<MaterialSignals>& signals);

}  // namespace haptex::evaluate
