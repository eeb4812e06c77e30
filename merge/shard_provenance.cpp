#include "merge/shard_provenance.hpp"

#include "core/sha256.hpp"
#include "dataset/layout.hpp"
#include "merge/root_attributes.hpp"

namespace haptex::merge {
namespace {
using namespace dataset::layout;
}  // namespace

void write_joined_root_attributes(h5::Group root, const std::vector<Shard>& shards, const MaterialPlan& plan) {
  for (const RootAttribute& a : root_attributes(shards.front().kind)) {
    std::vector<std::string> values;
    for (std::size_t s = 0; s < shards.size(); ++s)
      if (plan.contributes(s)) values.push_back(shards[s].attribute(a.name));
    root.set_attr(a.name, join_values(a.join, values));
  }
}

void write_shard_provenance(h5::Group root, const std::vector<Shard>& shards, const MaterialPlan& plan) {
  h5::Group all = root.create_group(kShards);
  for (std::size_t s = 0; s < shards.size(); ++s) {
    const Shard& shard = shards[s];
    h5::Group g = all.create_group(std::to_string(s));
    g.set_attr(kShardFile, shard.path);
    g.set_attr(kShardSha256, sha256_file(shard.path));
    g.set_attr(kShardMaterials, id_list(plan.taken_from(s)));
    g.set_attr(kShardLeftOut, id_list(plan.left_out_of(s)));
    for (const auto& [name, value] : shard.root_attributes) g.set_attr(name, value);
    const h5::Group shard_root = shard.file.root();
    if (shard_root.has_group(kShards)) g.copy_from(shard_root, kShards, kShards);
  }
}

}  // namespace haptex::merge
