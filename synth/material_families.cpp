#include "synth/material_families.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <random>

#include "core/random_seeds.hpp"

namespace haptex::synth {
namespace {

struct Family {
  const char* name;
  SurfaceRecipe surface;
  double resonance_hz;
};

// rms_um, correlation_mm, anisotropy, angle, pattern, period_mm, pattern height um, pattern angle
const std::array<Family, kFamilyCount>& families() {
  static const std::array<Family, kFamilyCount> list = {{
      {"Polished", {"polished", 0.6, 0.5, 1, 0, Pattern::none, 1, 0, 0}, 420},
      {"Sandpaper", {"sandpaper", 14, 0.06, 1, 0, Pattern::none, 1, 0, 0}, 300},
      {"Brushed", {"brushed", 4, 0.8, 8, 0, Pattern::none, 1, 0, 0}, 360},
      {"Grooved", {"grooved", 2, 0.2, 1, 0, Pattern::grooves, 0.8, 40, 0}, 260},
      {"Woven", {"woven", 5, 0.1, 1, 0, Pattern::weave, 1.2, 60, 0}, 180},
      {"Mesh", {"mesh", 3, 0.15, 1, 0, Pattern::mesh, 2.0, 50, 0}, 220},
      {"Dotted", {"dotted", 1.5, 0.3, 1, 0, Pattern::dots, 1.5, 80, 0}, 320},
      {"Pebbled", {"pebbled", 30, 0.5, 1, 0, Pattern::none, 1, 0, 0}, 150},
  }};
  return list;
}

}  // namespace

MaterialSpec material_spec(int index, std::uint64_t seed) {
  const Family& family = families()[std::size_t(index % kFamilyCount)];
  const int variant = index / kFamilyCount;
  MaterialSpec spec;
  spec.name = std::string(family.name) + " " + std::to_string(variant + 1);
  spec.surface = family.surface;
  spec.resonance_hz = family.resonance_hz;
  spec.seed = derive_seed(seed, 100 + std::uint64_t(index));
  std::mt19937_64 rng(derive_seed(seed, 200 + std::uint64_t(index)));
  std::uniform_real_distribution<double> angle(0, std::numbers::pi);
  spec.surface.angle_rad = angle(rng);
  spec.surface.pattern_angle_rad = angle(rng);
  if (variant == 0) return spec;
  // Variants: within +-15 % of the family's parameters, so a family stays recognisable.
  std::uniform_real_distribution<double> jitter(0.85, 1.15);
  spec.surface.rms_um *= jitter(rng);
  spec.surface.correlation_mm *= jitter(rng);
  spec.surface.pattern_period_mm *= jitter(rng);
  spec.surface.pattern_height_um *= jitter(rng);
  spec.resonance_hz *= jitter(rng);
  return spec;
}

std::vector<MaterialSpec> material_specs(int count, std::uint64_t seed) {
  std::vector<MaterialSpec> specs;
  for (int i = 0; i < count; ++i) specs.push_back(material_spec(i, seed));
  return specs;
}

}  // namespace haptex::synth
