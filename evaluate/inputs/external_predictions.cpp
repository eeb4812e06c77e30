#include "evaluate/inputs/external_predictions.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/h5/file.hpp"
#include "core/h5/link_rule.hpp"
#include "core/input_file.hpp"
#include "core/sha256.hpp"
#include "core/text/format.hpp"
#include "core/text/utf8.hpp"
#include "dataset/layout.hpp"
#include "dataset/window.hpp"

namespace haptex::evaluate {
namespace {

namespace layout = dataset::layout;

constexpr std::size_t kLongestName = 40;
constexpr const char* kRemake = "Predict again on the grid of `haptex windows DATASET --split SPLIT` (docs/benchmark.md)";
constexpr const char* kLayout = "Write the file as schemas/hdf5-layout.md (\"Predictions file\") lays it out; python/haptex_data.py's write_predictions does";
constexpr double kLargestAcceleration = dataset::kLargestAccelerationMs2;

struct Reader {
  const std::string& path;

  Error error(const std::string& object, const std::string& what, const std::string& fix = kRemake) const {
    return input_error(path, object, what, fix);
  }

  // The HDF5 layer's own refusals name the object but suggest haptex wrote the file: these carry this file's fix.
  template <typename Read>
  auto attribute(const std::string& where, const char* expected, Read read) const {
    try {
      return read();
    } catch (const Error&) {
      throw error(where, "is not " + std::string(expected), kLayout);
    }
  }

  std::string text(const h5::Node& node, std::string_view name, const std::string& where) const {
    if (!node.has_attr(name)) throw error(where, "is missing");
    return attribute(where, "one UTF-8 string", [&] { return node.attr_string(name); });
  }

  void require_hash(const h5::Group& root, std::string_view name, const std::string& wanted, const std::string& of) const {
    const std::string where = "/@" + std::string(name);
    const std::string found = text(root, name, where);
    if (found != wanted)
      throw error(where, "is " + found.substr(0, 64) + ": the predictions were made for another " + of + " (whose SHA-256 is " + wanted + ")");
  }

  // An optional compute time: absent is NaN; present must be a positive number of seconds.
  double seconds(const h5::Node& node, std::string_view name, const std::string& where) const {
    if (!node.has_attr(name)) return kNotMeasured;
    const double v = attribute(where, "one number", [&] { return node.attr_double(name); });
    constexpr double kLongest = 1e6;  // seconds: 11 days for one query is no measured time
    if (!std::isfinite(v) || v <= 0 || v > kLongest)
      throw error(where, "is " + text::format("%g", v) + ", expected a compute time in seconds above 0 and at most 1e6",
                  "Write the measured time, or leave the attribute out (the method then has no point in the speed chart)");
    return v;
  }

  h5::Dataset floats(const h5::Group& g, const std::string& name, const std::string& where) const {
    if (!g.has_dataset(name)) throw error(where, g.has(name) ? "is not a dataset" : "is missing");
    h5::Dataset d = g.open_dataset(name);
    if (d.dtype() != "float32" && d.dtype() != "float64") throw error(where, "holds " + d.dtype() + ", expected float32 or float64");
    return d;
  }

  // Values must be finite; amplitudes (spectra) must not be negative either.
  // Values must be finite and at most kLargestAcceleration in size; amplitudes (spectra) must not be negative either.
  std::vector<double> values(const h5::Dataset& d, const std::string& where, bool amplitudes, std::size_t row_length) const {
    std::vector<double> v;
    try {
      v = d.read<double>();
    } catch (const Error&) {
      throw error(where, "cannot be read: HDF5 could not decode it (a compression filter other than gzip, or a damaged file)",
                  "Write it uncompressed or with gzip (h5py: compression=\"gzip\")");
    }
    for (std::size_t i = 0; i < v.size(); ++i) {
      const bool negative = amplitudes && v[i] < 0;
      if (std::isfinite(v[i]) && std::abs(v[i]) <= kLargestAcceleration && !negative) continue;
      const std::string place = row_length ? "row " + std::to_string(i / row_length) + ", bin " + std::to_string(i % row_length)
                                            : "sample " + std::to_string(i);
      throw error(where, place + " is " + text::format("%g", v[i]) + ", expected a finite " + (amplitudes ? "amplitude of 0" : "acceleration of -1e6") +
                             " to 1e6 m/s^2",
                  negative ? "Amplitude spectra are never negative: clamp the model's output at 0 (e.g. a ReLU or softplus)" : kRemake);
    }
    return v;
  }

  std::vector<std::vector<double>> spectra(const h5::Group& root, std::size_t rows) const {
    const h5::Dataset d = floats(root, layout::kPredictedSpectra, std::string("/") + layout::kPredictedSpectra);
    const h5::Shape want{rows, dataset::kTargetBins};
    if (d.shape() != want) {
      const bool other_grid = d.shape().size() == 2 && d.shape()[1] == dataset::kTargetBins;
      throw error("/spectra", "has shape " + h5::shape_text(d.shape()) + ", expected " + h5::shape_text(want) +
                                  (other_grid ? ": it was made for another grid (the grid of this dataset and split has " +
                                                    std::to_string(rows) + " windows)"
                                              : " (one 100-bin spectrum, 10..1000 Hz, per grid window)"));
    }
    const std::vector<double> flat = values(d, "/spectra", true, dataset::kTargetBins);
    std::vector<std::vector<double>> out(rows);
    for (std::size_t w = 0; w < rows; ++w)
      out[w].assign(flat.begin() + std::ptrdiff_t(w * dataset::kTargetBins), flat.begin() + std::ptrdiff_t((w + 1) * dataset::kTargetBins));
    return out;
  }

  std::vector<double> signal(const h5::Group& g, std::size_t k, const GridSection& s) const {
    const std::string where = "/signals/" + std::to_string(k);
    const h5::Dataset d = floats(g, std::to_string(k), where);
    const h5::Shape shape = d.shape();
    if (shape.size() != 1 || shape[0] < s.covered || shape[0] > s.samples)
      throw error(where, "has shape " + h5::shape_text(shape) + ", expected " + std::to_string(s.covered) + " to " + std::to_string(s.samples) +
                             " samples: grid section " + std::to_string(k) + " has " + std::to_string(s.windows) + " windows over its first " +
                             std::to_string(s.covered) + " of " + std::to_string(s.samples) + " samples");
    return values(d, where, false, 0);
  }

  std::vector<std::vector<double>> signals(const h5::Group& root, const std::vector<GridSection>& grid) const {
    const h5::Group g = root.open_group(layout::kPredictedSignals);
    const std::vector<std::string> names = g.children();
    for (const std::string& name : names)
      if (name.empty() || name.size() > 9 || !std::all_of(name.begin(), name.end(), [](char c) { return c >= '0' && c <= '9'; }) ||
          (name.size() > 1 && name[0] == '0') || std::stoul(name) >= grid.size())
        throw error("/signals/" + name.substr(0, 80), "is not a grid section (0 to " + std::to_string(grid.size() - 1) + ")");
    if (names.size() != grid.size())
      throw error("/signals", "holds " + std::to_string(names.size()) + " signals, expected one per grid section: " + std::to_string(grid.size()));
    std::vector<std::vector<double>> out;
    for (std::size_t k = 0; k < grid.size(); ++k) out.push_back(signal(g, k, grid[k]));
    return out;
  }
};

// An argument as typed, cut to `most` bytes, with the bytes a terminal cannot show as '?'.
// The argument as a terminal may show it (README: names escaped, \xHH and \uHHHH), cut to `most` bytes.
std::string shown(const std::string& argument, std::size_t most) {
  return text::printable(std::string_view(argument).substr(0, most)) + (argument.size() > most ? "..." : "");
}

// Text shown in a report cell, a CSV field and a chart label: line breaks and other control characters become spaces.
std::string one_line(std::string text) {
  for (char& c : text)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
  return text;
}

bool name_character(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '-'; }

}  // namespace

void check_predictions_name(const std::string& name) {
  const bool fine = !name.empty() && name.size() <= kLongestName && std::isalnum(static_cast<unsigned char>(name[0])) &&
                    std::all_of(name.begin(), name.end(), name_character) && name.find("-vs-") == std::string::npos;
  if (fine) return;
  throw Error(Error::Kind::bad_input, "evaluate: --predictions name '" + shown(name, 80) +
                                            "' is not a report name: use 1 to 40 letters, digits, '_', '.' or '-', starting with a "
                                            "letter or digit and without \"-vs-\" (e.g. --predictions knn=preds.h5)");
}

PredictionsInput parse_predictions_argument(const std::string& argument) {
  const std::size_t equals = argument.find('=');
  if (equals == std::string::npos || equals == 0 || equals + 1 == argument.size())
    throw Error(Error::Kind::bad_input, "evaluate: --predictions '" + shown(argument, 200) +
                                            "' is not NAME=FILE: give the name the report shows and the predictions file, e.g. "
                                            "--predictions knn=preds.h5");
  PredictionsInput input{argument.substr(0, equals), argument.substr(equals + 1)};
  check_predictions_name(input.name);
  return input;
}

std::vector<GridSection> grid_sections(const std::vector<MaterialSignals>& signals) {
  std::vector<GridSection> out;
  for (std::size_t m = 0; m < signals.size(); ++m)
    for (const SectionSignals& s : signals[m].test) {
      const std::vector<std::size_t> offsets = section_grid(s.accel.size());
      if (!offsets.empty()) out.push_back({m, offsets.size(), offsets.back() + dataset::kWindowSamples, s.accel.size()});
    }
  return out;
}

std::string ExternalPredictions::description() const { return one_line(source.empty() ? path : source); }

ExternalPredictions read_external_predictions(const PredictionsInput& input, const split::DatasetSplit& split,
                                              const std::vector<GridSection>& grid) {
  const Reader r{input.path};
  require_regular_file(input.path);  // a FIFO or a device is named as such
  // Only "not HDF5" is the layout's to fix: damage, a writer's lock or permissions are said as File::open
  // says them, with their place (review 31, F2).
  if (h5::not_hdf5(input.path)) throw r.error("", "is not an HDF5 file", kLayout);
  const h5::File file = h5::File::open(input.path);
  const h5::Group root = file.root();
  h5::require_link_rule(root);  // before any lookup by name: an external link to a FIFO would hang it (review 5)
  const std::string format = "/@" + std::string(layout::kPredictionsFormatAttribute);
  if (const std::string found = r.text(root, layout::kPredictionsFormatAttribute, format); found != layout::kPredictionsFormat)
    throw r.error(format, "is '" + found.substr(0, 80) + "', expected '" + std::string(layout::kPredictionsFormat) + "'",
                  "Write the file as schemas/hdf5-layout.md (\"Predictions file\") lays it out");
  r.require_hash(root, "dataset_sha256", split.dataset_sha256, "dataset than " + split.dataset_path);
  r.require_hash(root, "split_sha256", split.manifest_sha256, "split than " + split.manifest_path);
  std::size_t windows = 0;
  for (const GridSection& s : grid) windows += s.windows;
  ExternalPredictions p{input.name, input.path, sha256_file(input.path), {}, {}, {}, kNotMeasured, kNotMeasured};
  if (root.has_attr(layout::kPredictionsSource))
    p.source = one_line(r.text(root, layout::kPredictionsSource, std::string("/@") + layout::kPredictionsSource));
  p.query_seconds = r.seconds(root, layout::kQuerySeconds, std::string("/@") + layout::kQuerySeconds);
  p.spectra = r.spectra(root, windows);
  if (root.has(layout::kPredictedSignals)) {
    if (!root.has_group(layout::kPredictedSignals)) throw r.error(std::string("/") + layout::kPredictedSignals, "is not a group");
    p.signals = r.signals(root, grid);
    p.signal_seconds = r.seconds(root.open_group(layout::kPredictedSignals), layout::kSignalSeconds,
                                 std::string("/") + layout::kPredictedSignals + "/@" + layout::kSignalSeconds);
  }
  return p;
}

}  // namespace haptex::evaluate
