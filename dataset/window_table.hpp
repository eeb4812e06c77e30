#pragma once
// The /windows table of a dataset file (schemas/hdf5-layout.md, "Dataset file"): which material,
// recording and start sample each model window has (dataset/window.hpp), with its cached action and
// target spectrum. align writes it; split, train and evaluate read it through read_window_table.
#include <cstdint>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "core/h5/file.hpp"
#include "dataset/window.hpp"

namespace haptex::dataset {

struct WindowTable {
  std::vector<std::string> materials;  // material ids, indexed by `material`
  std::vector<std::int32_t> material, recording;
  std::vector<std::int64_t> start;
  std::vector<float> action;  // rows of kActionValues: force then speed
  std::vector<float> target;  // rows of kTargetBins, m/s^2
  std::size_t stride = kGridStride;

  std::size_t size() const { return start.size(); }
  std::span<const float> action_of(std::size_t w) const { return std::span(action).subspan(w * kActionValues, kActionValues); }
  std::span<const float> target_of(std::size_t w) const { return std::span(target).subspan(w * kTargetBins, kTargetBins); }
};

// The most windows a dataset's recordings can have at `stride`: per recording, its samples / stride + 1,
// from the shapes alone. A table with more rows is damaged, and is refused before its columns are
// read (review 12, F4: 6 MB declaring 10 million rows cost 5 GB).
std::size_t most_windows(const h5::Group& root, std::size_t stride);

// Writes /windows with its attributes (stride and the contract's sizes).
void write_window_table(h5::Group root, const WindowTable& table);

// The table as the file states it, before it is held against this haptex's contract: the four
// attributes that describe the contract as stored, and the width of the action and target rows (0
// with the column left empty when it is missing or not a (windows, width) float matrix).
struct StatedWindowTable : WindowTable {
  std::int64_t action_samples = 0, window_samples = 0, action_end = 0, action_step = 0;
  std::size_t action_width = 0, target_width = 0;
};

// What is wrong with a table: the object at fault ("/windows/start", "/windows/@stride") and what.
struct WindowTableProblem {
  std::string where, what;
  std::string text() const { return where + " " + what; }
};

// The one reading of /windows (in a dataset or windows file), which both the commands (through
// read_window_table) and qa's dataset.windows check take. Returns the problem instead when /windows,
// /windows/materials (1-D strings) or a column (1-D integers: material, recording, start, of one
// length) is missing or malformed, an attribute is not one positive integer (action_end: non-negative),
// the attributes do not fit together, or there are more rows than the recordings can hold at the
// stride (most_windows: review 12, F4).
std::variant<StatedWindowTable, WindowTableProblem> read_stated_window_table(const h5::Group& root);

// Reads /windows of a dataset file (opened with open_checked(path, Kind::dataset)). Throws
// haptex::Error (bad_input) naming the file and the object when read_stated_window_table finds a
// problem, the action or target is not a (windows, 20) or (windows, 100) float matrix, or the
// attributes describe another contract than this haptex's; the fix is to align again.
WindowTable read_window_table(const h5::File& file);

}  // namespace haptex::dataset
