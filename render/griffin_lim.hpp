#pragma once
// Offline phase reconstruction of predicted magnitudes: the fast Griffin-Lim algorithm (Perraudin,
// Balazs, Sondergaard 2013), on the reconstruction frames of render/target_magnitudes.hpp.
//
// Griffin-Lim alternates two projections: impose the target magnitudes (keep the phase), then make
// the coefficients consistent (STFT of their least-squares inverse). FGLA adds momentum,
//   t_n = c_n + alpha (c_n - c_{n-1}),
// which converges far faster. Only t_n's phase is used, so the iteration keeps c_n - beta c_{n-1}
// with beta = alpha / (1 + alpha), as torchaudio and librosa do (c_0 = 0: no momentum on step 1).
#include <complex>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "render/target_magnitudes.hpp"

namespace haptex::render {

enum class InitialPhase { random, zero };
// The arithmetic of the iterations. float32 reaches the same spectral convergence as float64 to within
// 0.1 dB (tests/render/griffin_lim_test.cpp) in less time (docs/evaluate.md, "Offline: fast
// Griffin-Lim"); float64 is what the golden values of tests/golden/render pin.
enum class Precision { float32, float64 };

struct GriffinLimOptions {
  std::size_t iterations = 100;
  double momentum = 0.99;  // alpha in [0, 1); 0 is plain Griffin-Lim
  InitialPhase initial_phase = InitialPhase::random;
  std::uint64_t seed = 0;  // of the random initial phase (uniform in [0, 2 pi))
  Precision precision = Precision::float32;
};

// The signal of `length` samples whose STFT magnitudes approach s (frames x 501, non-negative).
// The frames cover covered_samples(s.frames) samples; a longer request is padded with zeros, a
// shorter one is cut. Allocates its working arrays once per call, nothing per iteration; the same
// options give the same signal. Throws haptex::Error for a bad shape, a negative or non-finite
// magnitude, or a momentum outside [0, 1).
std::vector<double> griffin_lim(const MagnitudeFrames& s, std::size_t length, const GriffinLimOptions& options = {});

// The magnitude projection shared with the online method: every X[k] gets magnitude s[k] and keeps
// its phase; where X[k] is 0 the phase is 0. Never produces NaN (s = 0 gives 0).
void impose_magnitude(std::span<std::complex<double>> X, std::span<const double> s);

}  // namespace haptex::render
