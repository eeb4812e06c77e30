#pragma once
// One input of `haptex merge` (docs/merge.md): a recordings, gelsight or dataset file, opened and
// checked whole before anything is written, so a bad shard is refused with nothing on disk.
#include <string>
#include <utility>
#include <vector>

#include "core/h5/file.hpp"
#include "dataset/format.hpp"

namespace haptex::merge {

struct Shard {
  std::string path;
  h5::File file;
  dataset::Kind kind;
  std::vector<std::string> materials;  // the ids under /materials, sorted
  // The stamp and the format's root attributes (merge/root_attributes.hpp), as the file holds them.
  std::vector<std::pair<std::string, std::string>> root_attributes;

  std::string attribute(const std::string& name) const;  // one of root_attributes; "" when absent
};

// The formats merge joins: their files hold materials that stand alone.
bool mergeable(dataset::Kind kind);

// Opens and checks a shard. Throws haptex::Error (bad_input) naming the file, the object and the
// fix when the name is not UTF-8, the file is not an HDF5 file haptex wrote, its format is not one
// merge joins (or an older version of one), it holds no material or a material group not named as a
// material id, or its root holds an object or attribute merge does not know how to join.
Shard open_shard(const std::string& path);

// Refuses (bad_input) shards of different formats, naming both files and formats, and a file given
// twice (by any name: a second spelling or a link is the same file).
void require_joinable(const std::vector<Shard>& shards);

}  // namespace haptex::merge
