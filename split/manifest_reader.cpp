#include "split/manifest_reader.hpp"

#include <algorithm>
#include <filesystem>

#include "core/error.hpp"
#include "core/json/schema.hpp"

namespace haptex::split {
namespace fs = std::filesystem;

SplitManifestDocument read_split_manifest(const std::string& path) { return {path, json::read_file(path)}; }

namespace {

// As `haptex split` allows (--sections, --val, --test: 3 to 10 000), and more presses than any
// material holds.
constexpr std::int64_t kMostSections = 10000;
constexpr std::size_t kMostPresses = 1000000;

// A list of section or press numbers: no longer than `most`, no number twice.
void check_numbers(const nlohmann::json& list, std::size_t most, const std::string& path, const std::string& where) {
  if (!list.is_array()) return;  // the schema names it
  if (list.size() > most)
    throw input_error(path, where, "lists " + std::to_string(list.size()) + " numbers, more than the " + std::to_string(most) + " a split holds",
                      "Make the split again with haptex split");
  std::vector<std::int64_t> numbers;
  for (const nlohmann::json& n : list)
    if (n.is_number_integer()) numbers.push_back(n.get<std::int64_t>());
  std::sort(numbers.begin(), numbers.end());
  if (const auto twice = std::adjacent_find(numbers.begin(), numbers.end()); twice != numbers.end())
    throw input_error(path, where, "lists " + std::to_string(*twice) + " twice", "Make the split again with haptex split");
}

void check_sizes(const nlohmann::json& doc, const std::string& path) {
  if (!doc.is_object()) return;
  if (const auto parameters = doc.find("parameters"); parameters != doc.end() && parameters->is_object())
    for (const char* key : {"sections", "val", "test"})
      if (const auto value = parameters->find(key); value != parameters->end() && value->is_number() && value->get<double>() > double(kMostSections))
        throw input_error(path, std::string("/parameters/") + key, "is " + value->dump() + ", more than the " + std::to_string(kMostSections) + " haptex split allows",
                          "Make the split again with haptex split");
  const auto materials = doc.find("materials");
  if (materials == doc.end() || !materials->is_array()) return;
  for (std::size_t m = 0; m < materials->size(); ++m) {
    const nlohmann::json& material = (*materials)[m];
    if (!material.is_object()) continue;
    for (const auto& [field, most] : {std::pair{"sections", std::size_t(kMostSections)}, std::pair{"presses", kMostPresses}}) {
      const auto sets = material.find(field);
      if (sets == material.end() || !sets->is_object()) continue;
      for (const char* set : kSetNames)
        if (const auto list = sets->find(set); list != sets->end())
          check_numbers(*list, most, path, "/materials/" + std::to_string(m) + "/" + field + "/" + set);
    }
  }
}

}  // namespace

void validate_split_manifest(const SplitManifestDocument& document) {
  check_sizes(document.json, document.path);
  json::validate(document.json, "split.schema.json", document.path);
}

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
