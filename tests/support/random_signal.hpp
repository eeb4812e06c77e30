#pragma once
// Seeded white Gaussian noise for signal tests: the same samples on every run and machine.
#include <random>
#include <vector>

namespace haptex::test {

inline std::vector<double> random_signal(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  std::vector<double> x(n);
  for (double& v : x) v = normal(rng);
  return x;
}

}  // namespace haptex::test
