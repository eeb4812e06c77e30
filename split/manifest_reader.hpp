#pragma once
// A split manifest (schemas/split.schema.json) as qa, train and evaluate read it: the raw JSON document for the
// schema check, and its fields once the schema holds.
#include <array>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace haptex::split {

enum class SplitSet { train = 0, val = 1, test = 2 };
inline constexpr std::array<const char*, 3> kSetNames = {"train", "val", "test"};

struct SplitMaterial {
  std::string id, name;
  std::int64_t recordings = 0;
  std::array<std::vector<std::int64_t>, 3> sections, presses;  // by SplitSet
  std::array<std::int64_t, 3> windows{};
  std::int64_t crossing = 0;
  double coverage_val = 0, coverage_test = 0;
};

struct SplitManifest {
  std::string dataset_path, dataset_sha256, recordings_sha256, gelsight_sha256;
  std::int64_t sections = 0, val = 0, test = 0;
  double min_coverage = 0;
  std::vector<SplitMaterial> materials;
  double worst_coverage = 0;
};

struct SplitManifestDocument {
  std::string path;
  nlohmann::json json;
};

// Reads the JSON; throws haptex::Error (bad_input) naming the file when it is not readable JSON.
SplitManifestDocument read_split_manifest(const std::string& path);
// Throws haptex::Error (bad_input) naming the file and the place unless the document satisfies
// split.schema.json. Its sizes and repeats (the schema's uniqueItems, which core/json leaves to this
// check) are checked first, in linear time: the schema validator compares every pair of a list's
// items and keeps an error per repeated pair, so 10 000 repeats took gigabytes and a million distinct
// numbers never finished (review 15, R6); `parameters.sections` bounds what the readers allocate (R5:
// 1e9 sections took 24 GB).
void validate_split_manifest(const SplitManifestDocument& document);
// The fields; call only once the document satisfies split.schema.json.
SplitManifest parse_split_manifest(const nlohmann::json& doc);
// The manifest's dataset file: its path as written, else relative to the manifest's folder, else
// the same file name beside the manifest; nullopt when none exists.
std::optional<std::string> locate_dataset(const SplitManifestDocument& manifest);

}  // namespace haptex::qa
