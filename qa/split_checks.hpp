#pragma once
// split.* (docs/qa.md, "Split manifests"): a manifest on its own and against the dataset file it was
// made from. check_split (qa/checkers.hpp) reads the dataset, assigns every material's sections to
// sets and recounts its windows once; each check_split_* function is one check of the catalog.
#include <array>
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/h5/file.hpp"
#include "qa/check.hpp"
#include "qa/window_table.hpp"
#include "split/manifest_reader.hpp"

namespace haptex::qa {

// The dataset file a manifest was made from, when it is at hand, and its window table.
struct SplitDataset {
  std::optional<std::string> path;
  std::optional<h5::File> file;
  std::string missing;  // why there is no file
  std::optional<WindowTable> table;
  std::string table_problem;        // why there is no table (no file, or unreadable)
  std::set<std::string> materials;  // those with windows in the table
};
SplitDataset open_split_dataset(const split::SplitManifest& m, const std::string& manifest_path,
                                const std::optional<std::string>& dataset_path);

// Which set each section of a material belongs to (-1: none); nullopt, with the problem, when its
// sections are out of range or in two sets.
struct MaterialSections {
  std::optional<std::vector<int>> set_of;
  std::string problem;
};
std::vector<MaterialSections> material_sections(const split::SplitManifest& m);

// What qa recomputes of one manifest material from the dataset's windows.
struct Recount {
  bool usable = false;  // its sections are valid and the dataset has its windows
  std::array<std::int64_t, 3> windows{};  // wholly inside a train, val, test section
  std::int64_t crossing = 0;
  std::array<std::optional<double>, 3> coverage;  // val and test inside the training hull; nullopt: no such windows
};
// One per manifest material; all unusable without a window table.
std::vector<Recount> recount_windows(const split::SplitManifest& m, const std::vector<MaterialSections>& sections,
                                     const SplitDataset& dataset);

CheckResult check_split_schema(const split::SplitManifestDocument& doc);
CheckResult check_split_hashes(const split::SplitManifest& m, const SplitDataset& dataset);
CheckResult check_split_materials(const split::SplitManifest& m, const SplitDataset& dataset);
CheckResult check_split_sections(const split::SplitManifest& m, const std::vector<MaterialSections>& sections);
CheckResult check_split_sets(const split::SplitManifest& m);
CheckResult check_split_crossing(const split::SplitManifest& m, const SplitDataset& dataset, const std::vector<Recount>& recount);
CheckResult check_split_coverage(const split::SplitManifest& m, const SplitDataset& dataset, const std::vector<Recount>& recount);
CheckResult check_split_coverage_recorded(const split::SplitManifest& m, const SplitDataset& dataset,
                                          const std::vector<Recount>& recount);
CheckResult check_split_presses(const split::SplitManifest& m, const SplitDataset& dataset);

}  // namespace haptex::qa
