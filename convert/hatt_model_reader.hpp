#pragma once
// Reads a HaTT model XML (Models_<Material>.xml, docs/convert.md) into ar::ModelSet.
#include <filesystem>
#include <string>
#include <string_view>

#include "core/ar/model_set.hpp"
#include "core/ar/piecewise_model.hpp"

namespace haptex::convert {

// Throws haptex::Error (bad input) naming the file, the element and its line, and what to do, when
// the file is unreadable, malformed or truncated, declares a DOCTYPE/ENTITY (refused: no entity
// expansion), lacks a required element, holds a non-numeric value, or when numMod, numTri or
// numARCoeff disagree with what the file lists, or a triangle names a model outside 1..numMod.
ar::ModelSet read_hatt_model(const std::filesystem::path& file);

// The same from text already in memory; `source` names it in error messages.
ar::ModelSet parse_hatt_model(std::string_view xml, const std::string& source);

// read_hatt_model followed by ar::PiecewiseArModel's checks (LSF ordering, vertex positions,
// triangle areas): a model ready to render.
ar::PiecewiseArModel load_hatt_model(const std::filesystem::path& file);

}  // namespace haptex::convert
