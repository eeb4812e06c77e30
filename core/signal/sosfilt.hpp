#pragma once
// Filtering with second-order sections, with scipy.signal semantics.
#include <span>
#include <vector>

#include "core/signal/butterworth.hpp"

namespace haptex::signal {

// scipy.signal.sosfilt_zi: per-section initial state (2 values each) for a unit step steady state.
std::vector<std::array<double, 2>> sosfilt_zi(const Sos& sos);

// scipy.signal.sosfilt with initial state zi (updated in place); transposed direct form II.
void sosfilt(const Sos& sos, std::span<double> x, std::vector<std::array<double, 2>>& zi);

// scipy.signal.sosfiltfilt(sos, x) with padtype='odd' and the default pad length
// 3 * (2 * sections + 1 - min(#(b2 == 0), #(a2 == 0))). Throws haptex::Error when x is not
// longer than the pad length.
std::vector<double> sosfiltfilt(const Sos& sos, std::span<const double> x);

// The pad length scipy's sosfiltfilt uses for this filter.
std::size_t sosfiltfilt_padlen(const Sos& sos);

}  // namespace haptex::signal
