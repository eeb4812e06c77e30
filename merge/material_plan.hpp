#pragma once
// Which shard each material of a merged file comes from (docs/merge.md). Shards are made per
// material, so a material in two shards is a mistake (the same material converted twice, or two
// materials named alike) unless the user says which copy to keep.
#include <cstddef>
#include <string>
#include <vector>

namespace haptex::merge {

struct MaterialSource {
  std::string id;
  std::size_t shard = 0;  // index into the shards, in command-line order
};

struct LeftOut {
  std::string id;
  std::size_t shard = 0, kept_from = 0;  // the shard whose copy is left out, and the one whose is kept
};

struct MaterialPlan {
  std::vector<MaterialSource> materials;  // sorted by id, as align and convert order them
  std::vector<LeftOut> left_out;          // with keep_first only

  bool contributes(std::size_t shard) const;         // whether any material comes from the shard
  std::vector<std::string> taken_from(std::size_t shard) const;
  std::vector<std::string> left_out_of(std::size_t shard) const;
};

// Material ids (lower case letters, digits and '_') separated by spaces: how messages and the
// merged file's /shards attributes list them (h5py users take them apart with .split()).
std::string id_list(const std::vector<std::string>& ids);

// materials[s] holds shard s's material ids; paths[s] names it in messages. Without keep_first a
// material in two shards is refused (haptex::Error, bad_input) naming both files and the material;
// with it, the first shard that has the material (in command-line order) gives it.
MaterialPlan plan_materials(const std::vector<std::vector<std::string>>& materials, const std::vector<std::string>& paths,
                            bool keep_first);

}  // namespace haptex::merge
