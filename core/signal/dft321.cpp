#include "core/signal/dft321.hpp"

#include <cmath>
#include <complex>
#include <string>

#include "core/error.hpp"
#include "core/signal/fft.hpp"

namespace haptex::signal {

std::vector<double> dft321(std::span<const double> x, std::span<const double> y, std::span<const double> z) {
  const std::size_t n = x.size();
  if (y.size() != n || z.size() != n)
    throw failure("DFT321: the acceleration axes have different lengths (" + std::to_string(x.size()) + ", " +
                  std::to_string(y.size()) + ", " + std::to_string(z.size()) + " samples)");
  if (n == 0) return {};
  const auto& fft = real_fft<double>(n);
  std::vector<std::complex<double>> X(fft.bins()), Y(fft.bins()), Z(fft.bins());
  fft.forward(x, X);
  fft.forward(y, Y);
  fft.forward(z, Z);
  // Reuse X for the combined spectrum: the energy of all three axes, the phase of their sum
  // (so components the axes share keep their timing).
  for (std::size_t k = 0; k < X.size(); ++k) {
    const double magnitude = std::sqrt(std::norm(X[k]) + std::norm(Y[k]) + std::norm(Z[k]));
    X[k] = std::polar(magnitude, std::arg(X[k] + Y[k] + Z[k]));
  }
  std::vector<double> out(n);
  fft.inverse(X, out);
  return out;
}

}  // namespace haptex::signal
