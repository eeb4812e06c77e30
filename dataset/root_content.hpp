#pragma once
// What haptex writes at the root of a recordings, gelsight or dataset file (schemas/hdf5-layout.md):
// the stamp, the format's own attributes, /materials, /shards and a dataset's /windows. merge refuses
// anything else (it has no rule to join it by) and qa's layout.required fails it, so the two agree.
#include <span>
#include <string>
#include <vector>

#include "core/h5/node.hpp"
#include "dataset/format.hpp"

namespace haptex::dataset {

// The root attributes of `kind` beside the stamp (core/h5/file.hpp); all are strings.
std::span<const char* const> root_attribute_names(Kind kind);

struct StrayRootContent {
  std::string where;   // "/@name" or "/name"
  std::string what;    // what is wrong with it
  std::string remove;  // how to remove it (an h5py line)
};

// Root attributes and objects of a recordings, gelsight or dataset file that haptex does not write
// there; none for other kinds, which have no such rule.
std::vector<StrayRootContent> stray_root_content(const h5::Group& root, Kind kind);

}  // namespace haptex::dataset
