#include "core/signal/crossfade.hpp"

#include <algorithm>
#include <cstddef>
#include <cmath>
#include <numbers>

namespace haptex::signal {

void append_crossfaded(std::vector<double>& out, std::span<const double> piece, std::size_t fade) {
  const std::size_t overlap = std::min({fade, out.size(), piece.size()});
  const std::size_t start = out.size() - overlap;
  for (std::size_t i = 0; i < overlap; ++i) {
    const double angle = std::numbers::pi / 2 * (double(i) + 0.5) / double(overlap);
    out[start + i] = out[start + i] * std::cos(angle) + piece[i] * std::sin(angle);
  }
  out.insert(out.end(), piece.begin() + std::ptrdiff_t(overlap), piece.end());
}

}  // namespace haptex::signal
