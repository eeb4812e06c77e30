#pragma once
// The `hatt-published` baseline: the toolkit's own model file for a material
// (Models_<Material>.xml in the directory given with --hatt-models DIR), rendered as published.
#include <filesystem>
#include <string_view>

#include "core/ar/piecewise_model.hpp"

namespace haptex::evaluate {

// The model file in `dir` for `material` (a display name such as "Brick 2" or an id such as
// "brick_2": both are compared through core/naming's material_id). A file matches when its name
// is Models_<Material>.xml (or <Material>.xml) with the same id; when no file name matches, the
// <material> element of every XML file in `dir` is read instead (files renamed by a user; files
// that are not HaTT models are passed over). Throws haptex::Error (bad input) when `dir` is not a
// directory, when nothing matches (naming the directory, the material and the closest file
// names), and when several files match (naming them).
std::filesystem::path find_hatt_model_file(const std::filesystem::path& dir, std::string_view material);

// find_hatt_model_file, then convert::load_hatt_model; throws as both do, and also when the file
// found by its name holds another <material>.
ar::PiecewiseArModel load_hatt_published(const std::filesystem::path& dir, std::string_view material);

}  // namespace haptex::evaluate
