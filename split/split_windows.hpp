#pragma once
// The dataset's windows and presses as a split manifest assigns them to train, validation and test:
// what `haptex train` and `haptex evaluate` read. The manifest must have been made from this very
// dataset file (its SHA-256), or the sets would silently mean other windows.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "split/manifest_reader.hpp"

namespace haptex::split {

enum : std::size_t { kTrain = 0, kVal = 1, kTest = 2 };

struct MaterialSets {
  std::string id, name;
  std::array<std::vector<std::size_t>, 3> rows;      // rows of /windows in each set; crossing windows in none
  std::array<std::vector<int>, 3> sections, presses;  // as the manifest lists them
  std::vector<std::int64_t> recording_samples;       // by recording number
};

struct DatasetSplit {
  std::string dataset_path, manifest_path, dataset_sha256, manifest_sha256;
  std::size_t sections = 0;
  std::vector<MaterialSets> materials;  // in the order of the dataset's /windows/materials
};

// Throws haptex::Error (bad_input) naming the file when the manifest does not satisfy
// split.schema.json, was made from another dataset (hash mismatch), or names other materials than
// the dataset holds.
DatasetSplit read_dataset_split(const std::string& dataset_path, const SplitManifestDocument& manifest);

}  // namespace haptex::split
