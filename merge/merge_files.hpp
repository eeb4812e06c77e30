#pragma once
// `haptex merge`: shards of one format (recordings, gelsight or dataset files made per material on
// several machines) joined into one file of that format, as if it had been made in one run
// (docs/merge.md; schemas/hdf5-layout.md, "Merged file").
#include <cstddef>
#include <string>
#include <vector>

#include "core/progress.hpp"
#include "dataset/format.hpp"
#include "merge/material_plan.hpp"

namespace haptex::merge {

struct MergeOptions {
  std::vector<std::string> shards;  // in the order given: the first wins with keep_first
  std::string output;
  bool overwrite = false;   // replaces only a file haptex wrote
  bool keep_first = false;  // a material in several shards is taken from the first, not refused
  std::string provenance;   // the command line, stored as the output's `source`
  // qa's integrity checks on every shard (qa/integrity.hpp). Off only where the shards' layout is
  // beside the point: the tests of the joining rules use skeleton shards.
  bool check_integrity = true;
};

struct MergeResult {
  dataset::Kind kind = dataset::Kind::recordings;
  MaterialPlan plan;
  std::size_t windows = 0;  // dataset files only
};

// Every shard is opened and checked (its integrity as qa checks it, then whether it can be joined),
// and every material placed, before the output is created, so
// bad input (haptex::Error, bad_input, naming the file, the object and the fix) leaves nothing
// written. Materials are copied whole (HDF5 object copy); a dataset's windows are concatenated and
// renumbered (merge/window_merge.hpp). Writes atomically.
MergeResult merge_files(const MergeOptions& options, const Progress& progress = {});

}  // namespace haptex::merge
