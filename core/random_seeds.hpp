#pragma once
// Independent, reproducible random streams (per material, recording, press, split try) from one user seed.
#include <cstdint>
#include <string_view>

namespace haptex {

// SplitMix64 over the combined inputs: well-mixed seeds, the same on every platform.
constexpr std::uint64_t derive_seed(std::uint64_t base, std::uint64_t a, std::uint64_t b = 0, std::uint64_t c = 0) {
  std::uint64_t x = base;
  for (std::uint64_t part : {a, b, c}) {
    x += 0x9E3779B97F4A7C15ULL + part;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
    x ^= x >> 31;
  }
  return x;
}

// FNV-1a of a name: a material's streams stay the same when other materials come and go.
constexpr std::uint64_t name_seed(std::string_view name) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (char c : name) h = (h ^ std::uint64_t(static_cast<unsigned char>(c))) * 0x100000001b3ULL;
  return h;
}

// A uniform draw in [0, 1) from 53 bits of the engine: unlike std::uniform_real_distribution,
// whose algorithm the standard leaves open, the same on every standard library.
template <typename Engine>
double unit_draw(Engine& engine) {
  return double(engine() >> 11) * 0x1.0p-53;
}

}  // namespace haptex
