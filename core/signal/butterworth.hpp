#pragma once
// Digital Butterworth low-pass design in second-order sections, as scipy.signal.butter(order, wn,
// output='sos') does it: analog prototype, pre-warped bilinear transform, zpk2sos with 'nearest' pairing.
#include <array>
#include <complex>
#include <vector>

namespace haptex::signal {

// One biquad: b0 b1 b2 a0 a1 a2 (a0 == 1), scipy's sos row layout.
using Section = std::array<double, 6>;
using Sos = std::vector<Section>;

// wn is the cut-off as a fraction of Nyquist, 0 < wn < 1; order >= 1.
Sos butter_lowpass(int order, double wn);
// Convenience: cut-off in Hz at sample rate fs.
Sos butter_lowpass_hz(int order, double cutoff_hz, double sample_rate_hz);

struct Zpk {
  std::vector<std::complex<double>> zeros, poles;
  double gain = 1.0;
};
// scipy.signal.zpk2sos(z, p, k, pairing='nearest') for a digital filter with real coefficients.
Sos zpk_to_sos(Zpk zpk);

}  // namespace haptex::signal
