#pragma once
// What a merged file keeps of its inputs (schemas/hdf5-layout.md, "Merged file"): the merged root's
// attributes joined from the shards' (merge/root_attributes.hpp), and per shard /shards/{s} with its
// path, SHA-256, stamp and root attributes as they were and which materials it gave, so every
// material can be traced to the file, the command and the inputs that made it.
#include <vector>

#include "core/h5/node.hpp"
#include "merge/material_plan.hpp"
#include "merge/shard.hpp"

namespace haptex::merge {

// The format's root attributes (beside the stamp) joined from the shards that give materials.
void write_joined_root_attributes(h5::Group root, const std::vector<Shard>& shards, const MaterialPlan& plan);

// /shards/{s} for every shard in command-line order. A shard that was itself merged brings its own
// /shards along as /shards/{s}/shards, so merges of merges keep every input.
void write_shard_provenance(h5::Group root, const std::vector<Shard>& shards, const MaterialPlan& plan);

}  // namespace haptex::merge
