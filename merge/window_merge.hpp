#pragma once
// The /windows table of a merged dataset file (schemas/hdf5-layout.md, "Dataset file"): every
// shard's windows of the materials taken from it, with the material index renumbered so each window
// still points at the same material, recording and samples. The recording number needs no change:
// it counts within the material, whose recordings are copied whole.
#include <string>
#include <vector>

#include "dataset/window_table.hpp"
#include "merge/material_plan.hpp"
#include "merge/shard.hpp"

namespace haptex::merge {

struct ShardWindows {
  std::string path;
  dataset::WindowTable table;
};

// A dataset shard's /windows (dataset::read_window_table's checks), and that every window points at
// data the shard holds: /windows/materials names exactly the shard's materials, every material index
// is in range and every recording number names a recording of its material. Throws haptex::Error
// (bad_input) naming the file and the object; the fix is to align the shard again.
ShardWindows read_shard_windows(const Shard& shard);

// For each planned material in order, its rows from the shard it comes from, in their order (align
// orders them by recording and start, so the merged table keeps the documented order). Refuses
// shards cut with different strides, naming both files.
dataset::WindowTable merge_windows(const std::vector<ShardWindows>& shards, const MaterialPlan& plan);

}  // namespace haptex::merge
