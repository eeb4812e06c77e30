#pragma once
// Procedural materials in families: materials of one family share a surface recipe up to small
// variations (near each other in look and feel), families differ in kind (far apart).
#include <cstdint>
#include <string>
#include <vector>

#include "synth/height_field.hpp"

namespace haptex::synth {

struct MaterialSpec {
  std::string name;         // "Woven 2"
  SurfaceRecipe surface;
  double resonance_hz = 250;  // contact resonance at 1 N; rises as F^(1/6) (Hertzian stiffness ~ F^(1/3))
  double damping = 0.15;
  std::uint64_t seed = 0;     // of this material's surface, presses and recordings
};

inline constexpr int kFamilyCount = 8;

// Material i of a set: family i % 8, variant i / 8 (variants of a family are jittered copies).
// The first 8 are the default demo set, one per family.
MaterialSpec material_spec(int index, std::uint64_t seed);
std::vector<MaterialSpec> material_specs(int count, std::uint64_t seed);

}  // namespace haptex::synth
