#include "predict/model.hpp"

#include <algorithm>

namespace haptex::predict {

std::string variant_name(Variant variant) { return variant == Variant::unified ? "unified" : "per-material"; }

int Model::material_index(const std::string& id) const {
  const auto found = std::find(material_ids.begin(), material_ids.end(), id);
  return found == material_ids.end() ? -1 : int(found - material_ids.begin());
}

}  // namespace haptex::predict
