#include "align/material_matching.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/json/schema.hpp"
#include "core/naming.hpp"

namespace haptex::align {
namespace {

const NamedMaterial* find_by_name(const std::vector<NamedMaterial>& list, const std::string& name) {
  const std::string key = material_id(name);
  for (const auto& m : list)
    if (m.id == key || material_id(m.name) == key) return &m;
  return nullptr;
}

}  // namespace

MaterialMatch match_materials(const std::vector<NamedMaterial>& recordings, const std::vector<NamedMaterial>& gelsight,
                              const std::map<std::string, std::string>& name_map, const std::string& map_file) {
  // gelsight id -> recordings material
  std::map<std::string, const NamedMaterial*> joined;
  for (const auto& [gelsight_name, recordings_name] : name_map) {
    const NamedMaterial* g = find_by_name(gelsight, gelsight_name);
    const NamedMaterial* r = find_by_name(recordings, recordings_name);
    if (!g) throw input_error(map_file, "\"" + gelsight_name + "\"", "no such material in the gelsight file", "Check the spelling, or remove the entry");
    if (!r) throw input_error(map_file, "\"" + gelsight_name + "\": \"" + recordings_name + "\"", "no such material in the recordings file", "Check the spelling, or remove the entry");
    joined[g->id] = r;
  }
  for (const auto& g : gelsight)
    if (!joined.count(g.id))
      if (const NamedMaterial* r = find_by_name(recordings, g.name.empty() ? g.id : g.name)) joined[g.id] = r;

  MaterialMatch match;
  std::map<std::string, std::string> taken;  // recordings id -> gelsight id already joined to it
  for (const auto& g : gelsight) {
    auto it = joined.find(g.id);
    if (it == joined.end()) {
      match.only_gelsight.push_back(g);
      continue;
    }
    const NamedMaterial& r = *it->second;
    if (auto previous = taken.find(r.id); previous != taken.end())
      throw input_error(map_file, "material '" + r.name + "'",
                        "is joined with two gelsight materials, '" + previous->second + "' and '" + g.id + "'",
                        "Give each material one name, or map exactly one of them with --names");
    taken[r.id] = g.id;
    match.pairs.push_back({r.id, r, g});
  }
  for (const auto& r : recordings)
    if (!taken.count(r.id)) match.only_recordings.push_back(r);
  std::sort(match.pairs.begin(), match.pairs.end(), [](const auto& a, const auto& b) { return a.id < b.id; });
  return match;
}

std::map<std::string, std::string> load_name_map(const std::string& path) {
  const nlohmann::json doc = json::read_file(path);
  json::validate(doc, "name-map.schema.json", path);
  return doc.get<std::map<std::string, std::string>>();
}

}  // namespace haptex::align
