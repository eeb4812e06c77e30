#include "split/manifest_reader.hpp"

#include <filesystem>

#include "core/json/schema.hpp"

namespace haptex::split {
namespace fs = std::filesystem;

SplitManifestDocument read_split_manifest(const std::string& path) { return {path, json::read_file(path)}; }

SplitManifest parse_split_manifest(const nlohmann::json& doc) {
  SplitManifest m;
  const auto& dataset = doc.at("dataset");
  m.dataset_path = dataset.at("path");
  m.dataset_sha256 = dataset.at("sha256");
  m.recordings_sha256 = dataset.at("recordings_sha256");
  m.gelsight_sha256 = dataset.at("gelsight_sha256");
  const auto& parameters = doc.at("parameters");
  m.sections = parameters.at("sections");
  m.val = parameters.at("val");
  m.test = parameters.at("test");
  m.min_coverage = parameters.at("min_coverage");
  m.worst_coverage = doc.at("worst_coverage");
  for (const auto& item : doc.at("materials")) {
    SplitMaterial material;
    material.id = item.at("id");
    material.name = item.at("name");
    material.recordings = item.at("recordings");
    for (std::size_t s = 0; s < 3; ++s) {
      material.sections[s] = item.at("sections").at(kSetNames[s]).get<std::vector<std::int64_t>>();
      material.presses[s] = item.at("presses").at(kSetNames[s]).get<std::vector<std::int64_t>>();
      material.windows[s] = item.at("windows").at(kSetNames[s]);
    }
    material.crossing = item.at("windows").at("crossing");
    material.coverage_val = item.at("coverage").at("val");
    material.coverage_test = item.at("coverage").at("test");
    m.materials.push_back(std::move(material));
  }
  return m;
}

std::optional<std::string> locate_dataset(const SplitManifestDocument& manifest) {
  const auto dataset = manifest.json.find("dataset");
  if (dataset == manifest.json.end() || !dataset->is_object() || !dataset->contains("path") ||
      !(*dataset)["path"].is_string())
    return std::nullopt;
  const fs::path written = (*dataset)["path"].get<std::string>();
  const fs::path folder = fs::path(manifest.path).parent_path();
  std::error_code ec;
  for (const fs::path& candidate : {written, folder / written, folder / written.filename()})
    if (!candidate.empty() && fs::is_regular_file(candidate, ec)) return candidate.string();
  return std::nullopt;
}

}  // namespace haptex::split
