#pragma once
// The root attributes each format carries beside the stamp (core/h5/file.hpp), and how a merged
// file's are made from its shards' (docs/merge.md, "Provenance"). A merged file came from several
// inputs, so an attribute naming one input becomes the list of them, and a hash of one input a hash
// that changes whenever any of them does; each shard's own values are kept under /shards.
#include <string>
#include <vector>

#include "core/h5/node.hpp"
#include "dataset/format.hpp"

namespace haptex::merge {

enum class Join {
  lines,   // the distinct values in shard order, one per line
  digest,  // the one distinct value, or the SHA-256 of the distinct values sorted, each followed by '\n'
};

struct RootAttribute {
  const char* name;
  Join join;
};

// The root attributes of `kind` beside the stamp (dataset/root_content.hpp), each with its join: a
// hash of inputs is joined into one hash, anything else into lines.
std::vector<RootAttribute> root_attributes(dataset::Kind kind);

// The merged value of one attribute from the values of the shards that contribute materials.
std::string join_values(Join join, const std::vector<std::string>& values);

}  // namespace haptex::merge
