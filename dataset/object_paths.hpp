#pragma once
// The paths of a file's material, recording and press groups as readers and messages quote them
// ("/materials/brick_2/recordings/0"), made of layout.hpp's names, so no module spells them out.
#include <string>
#include <string_view>

#include "dataset/layout.hpp"

namespace haptex::dataset {

// "/name": an object at a file's root.
inline std::string root_path(std::string_view name) { return "/" + std::string(name); }

inline std::string material_path(std::string_view id) { return std::string("/") + layout::kMaterials + "/" + std::string(id); }
inline std::string recordings_path(std::string_view id) { return material_path(id) + "/" + layout::kRecordings; }
inline std::string recording_path(std::string_view id, std::string_view k) { return recordings_path(id) + "/" + std::string(k); }
inline std::string recording_path(std::string_view id, int k) { return recording_path(id, std::to_string(k)); }
inline std::string presses_path(std::string_view id) { return material_path(id) + "/" + layout::kPresses; }
inline std::string press_path(std::string_view id, std::string_view j) { return presses_path(id) + "/" + std::string(j); }

// A model file's network k ("/nets/0"), a part of it ("/nets/0/predictor") and a layer of a part
// ("/nets/0/predictor/layers/1", "/texture_encoder/layers/0").
inline std::string net_path(int k) { return root_path(layout::kNets) + "/" + std::to_string(k); }
inline std::string net_part_path(int k, std::string_view part) { return net_path(k) + "/" + std::string(part); }
inline std::string layer_path(std::string_view part_path, std::size_t i) {
  return std::string(part_path) + "/" + layout::kLayers + "/" + std::to_string(i);
}
// "/materials/ids" of a model file.
inline std::string model_material_ids_path() { return material_path(layout::kMaterialIds); }

// The material id of a path inside /materials ("brick_2" of "/materials/brick_2/recordings/0").
inline std::string material_of(std::string_view path) {
  const std::size_t start = material_path("").size();
  return std::string(path.substr(start, path.find('/', start) - start));
}

}  // namespace haptex::dataset
