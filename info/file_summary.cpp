#include "info/file_summary.hpp"

#include <filesystem>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/h5/file.hpp"
#include "core/h5/link_rule.hpp"
#include "dataset/format.hpp"
#include "dataset/layout.hpp"

namespace haptex::info {
namespace {

using dataset::layout::kMaterials;

// An attribute a file may lack; one that is there but does not read (not UTF-8) is an error, not
// hidden: unlike qa, which reports it as a failed check (h5::Node::try_attr), info has no other way to say it.
std::string optional_string(const h5::Node& node, const char* name) {
  return node.has_attr(name) ? node.attr_string(name) : std::string();
}

DatasetSummary summarize_dataset(const h5::Dataset& dataset, const std::string& name) {
  DatasetSummary d{name, dataset.dtype(), optional_string(dataset, "units"), {}};
  for (auto extent : dataset.shape()) d.shape.push_back(extent);
  return d;
}

ItemSummary summarize_item(const h5::Group& group, const std::string& key) {
  ItemSummary item{key, {}, {}, optional_string(group, "source_file"), {}};
  if (group.has_attr(dataset::layout::kSampleRate)) item.sample_rate_hz = group.attr_double(dataset::layout::kSampleRate);
  if (group.has_attr(dataset::layout::kDuration)) item.duration_s = group.attr_double(dataset::layout::kDuration);
  for (const std::string& child : group.children())
    if (group.has_dataset(child)) item.datasets.push_back(summarize_dataset(group.open_dataset(child), child));
  return item;
}

MaterialSummary summarize_material(const h5::Group& group, const std::string& id) {
  MaterialSummary material{id, group.has_attr(dataset::layout::kName) ? group.attr_string(dataset::layout::kName) : id, {}};
  for (const std::string& collection_name : group.children()) {
    if (!group.has_group(collection_name)) continue;
    const h5::Group collection = group.open_group(collection_name);
    CollectionSummary summary{collection_name, {}};
    for (const std::string& key : collection.children())
      if (collection.has_group(key)) summary.items.push_back(summarize_item(collection.open_group(key), key));
    material.collections.push_back(std::move(summary));
  }
  return material;
}

void collect_datasets(const h5::Group& group, const std::string& prefix, std::vector<DatasetSummary>& out) {
  for (const std::string& child : group.children()) {
    if (prefix.empty() && child == kMaterials) continue;
    const std::string path = prefix + "/" + child;
    if (group.has_dataset(child)) out.push_back(summarize_dataset(group.open_dataset(child), path));
    else if (group.has_group(child)) collect_datasets(group.open_group(child), path, out);
  }
}

nlohmann::json dataset_json(const DatasetSummary& d) {
  return {{"name", d.name}, {"dtype", d.dtype}, {"shape", d.shape}, {"units", d.units}};
}

}  // namespace

FileSummary summarize_file(const std::string& path) {
  const h5::File file = h5::File::open(path);
  const h5::Group root = file.root();
  // Before any object is looked at by name: a name through an external link would open the file it
  // names, a FIFO among them (review 5). 'haptex qa' lists every link that breaks the rule.
  h5::require_link_rule(root);
  FileSummary summary;
  summary.path = path;
  summary.bytes = std::filesystem::file_size(path);
  summary.format = dataset::read_format_bytes(file);
  summary.format_remark = dataset::format_remark(summary.format);
  summary.version = optional_string(root, "haptex_version");
  summary.created_utc = optional_string(root, "created_utc");
  summary.source = optional_string(root, "source");
  if (root.has_group(kMaterials)) {
    const h5::Group materials = root.open_group(kMaterials);
    for (const std::string& id : materials.children())
      if (materials.has_group(id)) summary.materials.push_back(summarize_material(materials.open_group(id), id));
    // A model names its materials in two lists (review 6: predict said "use one of the ids haptex
    // info lists", and info listed none).
    if (materials.has_dataset(dataset::layout::kMaterialIds) && materials.has_dataset(dataset::layout::kMaterialNames)) {
      const std::vector<std::string> ids = materials.open_dataset(dataset::layout::kMaterialIds).read_strings(),
                                     names = materials.open_dataset(dataset::layout::kMaterialNames).read_strings();
      for (std::size_t i = 0; i < ids.size(); ++i) summary.materials.push_back({ids[i], i < names.size() ? names[i] : ids[i], {}});
    }
  }
  collect_datasets(root, "", summary.other_datasets);
  return summary;
}

nlohmann::json to_json(const FileSummary& s) {
  nlohmann::json materials = nlohmann::json::array();
  for (const auto& m : s.materials) {
    nlohmann::json collections = nlohmann::json::object();
    for (const auto& c : m.collections) {
      nlohmann::json items = nlohmann::json::array();
      for (const auto& item : c.items) {
        nlohmann::json datasets = nlohmann::json::array();
        for (const auto& d : item.datasets) datasets.push_back(dataset_json(d));
        nlohmann::json j = {{"key", item.key}, {"source", item.source}, {"datasets", datasets}};
        if (item.sample_rate_hz) j["sample_rate_hz"] = *item.sample_rate_hz;
        if (item.duration_s) j["duration_s"] = *item.duration_s;
        items.push_back(j);
      }
      collections[c.name] = items;
    }
    materials.push_back({{"id", m.id}, {"name", m.name}, {"collections", collections}});
  }
  nlohmann::json others = nlohmann::json::array();
  for (const auto& d : s.other_datasets) others.push_back(dataset_json(d));
  nlohmann::json out = {{"path", s.path},           {"bytes", s.bytes},     {"format", s.format},
                        {"haptex_version", s.version}, {"created_utc", s.created_utc}, {"source", s.source},
                        {"materials", materials},   {"other_datasets", others}};
  if (!s.format_remark.empty()) out["format_remark"] = s.format_remark;
  return out;
}

}  // namespace haptex::info
