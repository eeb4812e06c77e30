#include "merge/material_plan.hpp"

#include <algorithm>
#include <map>

#include "core/error.hpp"
#include "dataset/layout.hpp"

namespace haptex::merge {

std::string id_list(const std::vector<std::string>& ids) {
  std::string text;
  for (const std::string& id : ids) text += (text.empty() ? "" : " ") + id;
  return text;
}

bool MaterialPlan::contributes(std::size_t shard) const {
  return std::any_of(materials.begin(), materials.end(), [&](const MaterialSource& m) { return m.shard == shard; });
}

std::vector<std::string> MaterialPlan::taken_from(std::size_t shard) const {
  std::vector<std::string> ids;
  for (const MaterialSource& m : materials)
    if (m.shard == shard) ids.push_back(m.id);
  return ids;
}

std::vector<std::string> MaterialPlan::left_out_of(std::size_t shard) const {
  std::vector<std::string> ids;
  for (const LeftOut& l : left_out)
    if (l.shard == shard) ids.push_back(l.id);
  return ids;
}

MaterialPlan plan_materials(const std::vector<std::vector<std::string>>& materials, const std::vector<std::string>& paths,
                            bool keep_first) {
  std::map<std::string, std::size_t> first_shard;  // sorted by id
  MaterialPlan plan;
  for (std::size_t s = 0; s < materials.size(); ++s)
    for (const std::string& id : materials[s]) {
      const auto [at, inserted] = first_shard.emplace(id, s);
      if (inserted) continue;
      if (!keep_first)
        throw input_error(paths[s], "/" + std::string(dataset::layout::kMaterials) + "/" + id, "material '" + id + "' is also in " + paths[at->second],
                          "Leave one of the two files out, or pass --keep-first to take each material from the first shard that has it");
      plan.left_out.push_back({id, s, at->second});
    }
  for (const auto& [id, s] : first_shard) plan.materials.push_back({id, s});
  return plan;
}

}  // namespace haptex::merge
