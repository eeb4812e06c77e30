#pragma once
// The /windows table of a dataset file (schemas/hdf5-layout.md, "Dataset file"): which material,
// recording and start sample each model window has (dataset/window.hpp), with its cached action and
// target spectrum. align writes it; split, train and evaluate read it through read_window_table.
#include <cstdint>
#include <span>
#include <string>
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

// Reads /windows of a dataset file (opened with open_checked(path, Kind::dataset)). Throws
// haptex::Error (bad_input) naming the file and the object when a column is missing, of another
// type or shape than documented, the columns differ in length, or the attributes describe another
// contract than this haptex's; the fix is to align again.
WindowTable read_window_table(const h5::File& file);

}  // namespace haptex::dataset
