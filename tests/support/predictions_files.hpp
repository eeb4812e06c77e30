#pragma once
// Predictions files (schemas/hdf5-layout.md, "Predictions file") written as a model trained outside
// haptex would write them, from the grid of haptex windows: the perfect predictor of the evaluation
// tests and the starting point of every hostile one.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/h5/node.hpp"

namespace haptex::test {

// A windows file's grid, read with the HDF5 library alone.
struct GridTable {
  std::string dataset_sha256, split_sha256;
  std::vector<std::string> materials;
  std::vector<std::int32_t> material, recording, section;
  std::vector<std::int64_t> start;
  std::vector<float> target;  // rows x 100
  std::size_t rows() const { return start.size(); }
};
GridTable read_grid(const std::string& windows_file);

// The grid's test sections in its order: rows [first_row, first_row + rows), windows from sample
// first_start of the recording, covering `covered` samples.
struct GridSpan {
  std::size_t first_row = 0, rows = 0;
  std::int64_t first_start = 0;
  std::size_t covered = 0;
};
std::vector<GridSpan> grid_spans(const GridTable& grid);

struct Predictions {
  std::string format = "predictions/1", dataset_sha256, split_sha256, source = "tests";
  std::vector<float> spectra;
  h5::Shape shape;  // of spectra; empty: no /spectra
  std::optional<double> query_seconds;
  std::vector<std::vector<float>> signals;  // one per grid span; none: no /signals
};

// Spectra: the grid's own targets (distance 0); signals, when the dataset is given: the recording's
// DFT321 acceleration over each span (distance 0 too).
Predictions perfect_predictions(const GridTable& grid, const std::string& dataset = "");

void write_predictions(const std::string& path, const Predictions& p);

}  // namespace haptex::test
