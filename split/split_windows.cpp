#include "split/split_windows.hpp"

#include <map>

#include "core/error.hpp"
#include "core/json/schema.hpp"
#include "core/sha256.hpp"
#include "dataset/format.hpp"
#include "split/dataset_view.hpp"
#include "split/manifest_reader.hpp"
#include "split/split_search.hpp"

namespace haptex::split {
namespace {

std::vector<int> as_ints(const std::vector<std::int64_t>& values) { return {values.begin(), values.end()}; }

std::map<std::string, const SplitMaterial*> by_id(const SplitManifest& manifest) {
  std::map<std::string, const SplitMaterial*> out;
  for (const SplitMaterial& m : manifest.materials) out[m.id] = &m;
  return out;
}

MaterialSets assign(const MaterialWindows& windows, const SplitMaterial& listed, std::size_t sections) {
  MaterialSets out{windows.id, windows.name, {}, {}, {}, windows.recording_samples};
  for (std::size_t s = 0; s < 3; ++s) {
    out.sections[s] = as_ints(listed.sections[s]);
    out.presses[s] = as_ints(listed.presses[s]);
  }
  const Sets sets{out.sections[kTrain], out.sections[kVal], out.sections[kTest]};
  const std::vector<int> section = window_sections(windows, sections);
  for (std::size_t i = 0; i < section.size(); ++i) {
    const int set = section[i] < 0 ? -1 : set_of_section(sets, section[i]);
    if (set >= 0) out.rows[std::size_t(set)].push_back(windows.row[i]);
  }
  return out;
}

}  // namespace

DatasetSplit read_dataset_split(const std::string& dataset_path, const SplitManifestDocument& document) {
  const std::string& manifest_path = document.path;
  // A damaged dataset, or a recordings or gelsight file given for one, is named as such, not as
  // "another dataset" by its hash.
  dataset::open_checked(dataset_path, dataset::Kind::dataset);
  validate_split_manifest(document);
  const SplitManifest manifest = parse_split_manifest(document.json);
  DatasetSplit out{dataset_path, manifest_path, sha256_file(dataset_path), sha256_file(manifest_path),
                   std::size_t(manifest.sections), {}};
  if (out.dataset_sha256 != manifest.dataset_sha256)
    throw input_error(manifest_path, "dataset.sha256",
                      "the split was made from another dataset than " + dataset_path + " (SHA-256 " +
                          manifest.dataset_sha256.substr(0, 12) + "... vs " + out.dataset_sha256.substr(0, 12) + "...)",
                      "Give the dataset the split was made from, or run haptex split on this dataset");
  const auto listed = by_id(manifest);
  for (const MaterialWindows& windows : read_dataset_windows(dataset_path)) {
    const auto found = listed.find(windows.id);
    if (found == listed.end())
      throw input_error(manifest_path, "materials", "material '" + windows.id + "' of the dataset is not in the split",
                        "Run haptex split on this dataset");
    out.materials.push_back(assign(windows, *found->second, out.sections));
  }
  if (out.materials.size() != manifest.materials.size())
    throw input_error(manifest_path, "materials", "the split lists materials the dataset does not hold",
                      "Run haptex split on this dataset");
  return out;
}

}  // namespace haptex::split
