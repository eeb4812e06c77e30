#include "tests/render/texture_signal.hpp"

#include <cmath>
#include <numbers>

#include "core/ar/gaussian_noise.hpp"
#include "core/signal/sosfilt.hpp"

namespace haptex::test {

std::vector<double> texture_signal(std::size_t n, std::uint64_t seed) {
  constexpr double kRate = 10000.0;
  const double resonances_hz[] = {80, 150, 230, 310, 420, 600, 900, 1500};
  const double radii[] = {0.995, 0.99, 0.99, 0.985, 0.98, 0.98, 0.97, 0.96};
  signal::Sos sos;
  for (std::size_t i = 0; i < 8; ++i) {
    const double r = radii[i], theta = 2.0 * std::numbers::pi * resonances_hz[i] / kRate;
    sos.push_back({1.0, 0.0, 0.0, 1.0, -2.0 * r * std::cos(theta), r * r});
  }
  ar::GaussianNoise noise(seed);
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double speed = 70.0 + 50.0 * std::sin(2.0 * std::numbers::pi * 0.7 * double(i) / kRate);
    x[i] = noise.next() * std::sqrt(speed / 70.0);
  }
  std::vector<std::array<double, 2>> state(sos.size(), {0.0, 0.0});
  signal::sosfilt(sos, x, state);
  double power = 0.0;
  for (double v : x) power += v * v;
  const double scale = 1.0 / std::sqrt(power / double(n));
  for (double& v : x) v *= scale;
  return x;
}

}  // namespace haptex::test
