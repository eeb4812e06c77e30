#pragma once
// Burg's method for AR estimation, as MATLAB's arburg: no mean removal, E0 = x'x / N.
#include <cstddef>
#include <span>
#include <vector>

namespace haptex::ar {

struct ArFit {
  std::vector<double> a;           // [1, a1, ..., ap]: y[n] = e[n] - sum a_i y[n-i]
  double variance = 0.0;           // final prediction-error variance (arburg's second output)
  std::vector<double> reflection;  // k1..kp (arburg's third output)
};

// Throws haptex::Error when order < 1, x has no more than `order` samples, x is not finite, or
// x is identically zero (the reflection coefficients are undefined).
ArFit burg(std::span<const double> x, std::size_t order);

}  // namespace haptex::ar
