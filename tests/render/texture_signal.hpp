#pragma once
// A texture-like vibration for the reconstruction tests and benchmarks: what the HaTT models
// render (AR-filtered Gaussian noise whose variance follows the stroke speed), made without a
// model file. tests/golden/render_golden.py's texture_like() is the same recipe in numpy.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace haptex::test {

// n samples at 10 kHz: white noise scaled by sqrt(speed / 70) with speed = 70 + 50 sin(2 pi 0.7 t)
// mm/s, through eight resonators (80..1500 Hz, pole radii 0.96..0.995: an AR(16) filter run as
// second-order sections), normalised to unit RMS.
std::vector<double> texture_signal(std::size_t n, std::uint64_t seed);

}  // namespace haptex::test
