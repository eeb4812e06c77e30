#pragma once
// DFT321 (Landin et al. 2010): three acceleration axes to one signal with the same spectral energy.
#include <span>
#include <vector>

namespace haptex::signal {

// Over the whole recording at once: per rfft bin |Y| = sqrt(sum_k |U_k|^2) and
// arg Y = arg(sum_k U_k); y = irfft(Y, n). All three axes must have the same length.
std::vector<double> dft321(std::span<const double> x, std::span<const double> y, std::span<const double> z);

}  // namespace haptex::signal
