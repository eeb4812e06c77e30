#pragma once
// How a signal's power divides between frequency bands: the whole recording, mean removed, under a
// Hann window (its side lobes fall fast enough that a stroke's large, slow force and speed changes do
// not leak into the bands above 40 Hz the filter checks look at).
#include <span>

namespace haptex::qa {

struct BandPower {
  double total = 0;  // mean square of the signal (mean removed)
  double band = 0;   // the part of it between low_hz and high_hz
  double share() const { return total > 0 ? band / total : 0.0; }
};

// Mean squares estimated from the windowed spectrum (Parseval, corrected for the window's power).
BandPower band_power(std::span<const double> x, double sample_rate_hz, double low_hz, double high_hz);

}  // namespace haptex::qa
