#pragma once
// Seeded standard-normal samples: std::mt19937_64 + Box-Muller written out here, so a seed gives the
// same sequence with every standard library (std::normal_distribution's algorithm is unspecified).
#include <cstdint>
#include <random>

namespace haptex::ar {

class GaussianNoise {
 public:
  explicit GaussianNoise(std::uint64_t seed) : engine_(seed) {}

  // The next N(0, 1) sample.
  double next();

 private:
  double uniform_open();  // in (0, 1]: log() never sees 0

  std::mt19937_64 engine_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

}  // namespace haptex::ar
