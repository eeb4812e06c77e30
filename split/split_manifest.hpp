#pragma once
// The split manifest (schemas/split.schema.json): inputs' hashes, parameters, and per material the
// sections, windows, coverage and presses of each set.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "split/split_search.hpp"

namespace haptex::split {

inline constexpr const char* kManifestFormat = "split/1";  // schemas/split.schema.json

nlohmann::json manifest_json(const std::string& dataset_path, const SplitOptions& options,
                             const std::vector<MaterialSplit>& materials, const std::string& source);

}  // namespace haptex::split
