#include "core/ar/gaussian_noise.hpp"

#include <cmath>
#include <numbers>

namespace haptex::ar {

double GaussianNoise::uniform_open() {
  // 53 random bits, shifted by one step so the result is never 0.
  return (double(engine_() >> 11) + 1.0) * 0x1.0p-53;
}

double GaussianNoise::next() {
  if (has_spare_) {
    has_spare_ = false;
    return spare_;
  }
  const double radius = std::sqrt(-2.0 * std::log(uniform_open()));
  const double angle = 2.0 * std::numbers::pi * uniform_open();
  spare_ = radius * std::sin(angle);
  has_spare_ = true;
  return radius * std::cos(angle);
}

}  // namespace haptex::ar
