#pragma once
// Predictions of a model trained outside haptex (docs/benchmark.md; schemas/hdf5-layout.md,
// "Predictions file"): one spectrum per window of the evaluation grid, and optionally one time
// signal per test section. Everything is checked against the grid before anything is scored, so a
// file made for another dataset, split or grid is refused, naming what differs.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "evaluate/evaluation_results.hpp"
#include "evaluate/inputs/section_signals.hpp"
#include "split/split_windows.hpp"

namespace haptex::evaluate {

// `--predictions NAME=FILE` as given.
struct PredictionsInput {
  std::string name, path;
};

// Splits "NAME=FILE" at its first '=' and checks NAME (check_predictions_name). Throws
// haptex::Error (bad_input) when there is no '=' or either side is empty.
PredictionsInput parse_predictions_argument(const std::string& argument);

// A name the report can use in experiment ids, file names and charts: 1 to 40 letters, digits,
// '_', '.' or '-', starting with a letter or digit, without "-vs-" (which would read as another
// comparison). Throws haptex::Error (bad_input) otherwise.
void check_predictions_name(const std::string& name);

// One test section of the grid, in the grid's order (sections without a window are not in it).
struct GridSection {
  std::size_t material = 0;  // index into the signals (the split's materials)
  std::size_t windows = 0;   // grid windows in the section
  std::size_t covered = 0;  // samples from the section's first through its last window's end
  std::size_t samples = 0;  // the section's length
};
std::vector<GridSection> grid_sections(const std::vector<MaterialSignals>& signals);

struct ExternalPredictions {
  std::string name, path, sha256;
  std::string source;                        // the file's /@source: how it was made ("" when absent)
  std::vector<std::vector<double>> spectra;  // one 100-bin amplitude spectrum per grid window, in the grid's order
  std::vector<std::vector<double>> signals;  // none, or one per grid section (10 kHz, from the section's first sample)
  double query_seconds = kNotMeasured;       // compute time of one window's prediction, one query at a time
  double signal_seconds = kNotMeasured;      // compute time of all the signals
  // How a chart or table describes it: the source, or without one the path, on one line.
  std::string description() const;
};

// Reads and checks a predictions file against the split's hashes and the grid. Throws
// haptex::Error (bad_input) naming the file, the object and the fix: not HDF5, another format,
// another dataset or split (hashes), another grid (row or section count, a signal shorter than its
// section's windows or longer than the section), a type or shape other than the layout's, a value
// that is not finite or (spectra) negative, a compute time that is not a positive number.
ExternalPredictions read_external_predictions(const PredictionsInput& input, const split::DatasetSplit& split,
                                              const std::vector<GridSection>& grid);

}  // namespace haptex::evaluate
