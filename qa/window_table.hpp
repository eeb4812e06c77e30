#pragma once
// The /windows table of a dataset file (schemas/hdf5-layout.md "Dataset file"): which material,
// recording and start sample each model window has, with its cached action and target.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/h5/node.hpp"
#include "dataset/window_table.hpp"

namespace haptex::qa {

// The table as the file states it (dataset::read_stated_window_table, the one reading of /windows):
// dataset.windows compares its attributes and widths with the contract (dataset/window.hpp) instead
// of refusing the file, as dataset::read_window_table does.
struct WindowTable : dataset::StatedWindowTable {
  // The first and one-past-last sample window w uses: [t, t + window_samples); its action samples are
  // t + action_end - (action_samples - 1 - j) action_step, j = 0 .. action_samples - 1.
  std::int64_t first_sample(std::size_t w) const { return start[w]; }
  std::int64_t end_sample(std::size_t w) const { return start[w] + window_samples; }
};

// The table, or nullopt with `problem` saying what is missing or inconsistent, or which attributes do
// not fit together (layout.* reports it).
std::optional<WindowTable> load_window_table(const h5::Group& root, std::string& problem);

// The `samples` attribute of /materials/{id}/recordings/{k}, when that recording exists.
std::optional<std::int64_t> recording_samples(const h5::Group& root, const std::string& material, std::int32_t recording);

}  // namespace haptex::qa
