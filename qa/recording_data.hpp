#pragma once
// The recordings of a recordings or dataset file (/materials/{material}/recordings/{k}), read one at
// a time for the signal, filter and duplicate checks. A signal that is missing or misshapen is kept
// as a problem, not an exception: the layout checks report it, the others skip it.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/h5/node.hpp"

namespace haptex::qa {

struct Signal {
  std::vector<double> values;  // row-major: rows x columns
  std::size_t rows = 0, columns = 1;
  std::string problem;         // why it could not be read; empty when values are valid
  bool ok() const { return problem.empty(); }
  double at(std::size_t row, std::size_t column = 0) const { return values[row * columns + column]; }
  std::vector<double> column(std::size_t c) const;
};

struct LoadedRecording {
  std::string path;  // /materials/{material}/recordings/{k}
  std::string material;
  std::optional<double> sample_rate_hz, duration_s;
  std::optional<std::int64_t> samples;
  std::optional<std::string> source_sha256;
  // How the signals were made (filter.stated): the low-pass's order and cut-off, the reduction's frames.
  std::optional<std::int64_t> lowpass_order, reduction_window, reduction_hop;
  std::optional<double> lowpass_cutoff_hz;
  std::map<std::string, Signal> signals;  // by dataset name; every name in kSignalNames is present

  // The sample rate to analyse spectra with: the file's, or 10 kHz when it has none.
  double analysis_rate() const;
};

// Datasets read per recording, with their column count: accel 1, accel_xyz 3, ...
struct SignalSpec {
  const char* name;
  std::size_t columns;
  bool optional;
};
extern const std::vector<SignalSpec> kSignalSpecs;

std::vector<std::string> recording_paths(const h5::Group& root);
LoadedRecording load_recording(const h5::Group& root, const std::string& path);

}  // namespace haptex::qa
