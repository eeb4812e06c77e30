#pragma once
// What a dataset's values mean, as every haptex file states it: a `units` attribute (none for counts,
// indices and images) and a one-line `description` (schemas/hdf5-layout.md).
#include <string>

#include "core/h5/node.hpp"

namespace haptex::dataset {

// Sets d's units (when not empty) and description; returns d.
h5::Dataset describe(h5::Dataset d, const std::string& units, const std::string& description);

}  // namespace haptex::dataset
