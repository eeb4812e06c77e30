#include "render/spectral_convergence.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "core/error.hpp"

namespace haptex::render {

MagnitudeFrames stft_magnitudes(std::span<const double> x) {
  const auto S = signal::stft(x, kReconstructionStft);
  MagnitudeFrames out;
  out.frames = S.frames;
  out.bins = S.bins;
  out.values.resize(S.values.size());
  for (std::size_t i = 0; i < S.values.size(); ++i) out.values[i] = std::abs(S.values[i]);
  return out;
}

double spectral_convergence_db(const MagnitudeFrames& reconstructed, const MagnitudeFrames& s) {
  if (reconstructed.frames != s.frames || reconstructed.bins != s.bins ||
      reconstructed.values.size() != s.values.size() || s.values.size() != s.frames * s.bins)
    throw failure("spectral convergence: the reconstruction has " + std::to_string(reconstructed.frames) + " x " +
                  std::to_string(reconstructed.bins) + " magnitudes, the target " + std::to_string(s.frames) +
                  " x " + std::to_string(s.bins) + "; they must match");
  double error = 0.0, target = 0.0;
  for (std::size_t i = 0; i < s.values.size(); ++i) {
    const double d = reconstructed.values[i] - s.values[i];
    error += d * d;
    target += s.values[i] * s.values[i];
  }
  if (target == 0.0) return (error == 0.0 ? -1.0 : 1.0) * std::numeric_limits<double>::infinity();
  return 10.0 * std::log10(error / target);  // 20 log10 of the ratio of the norms
}

double spectral_convergence_db(std::span<const double> x, const MagnitudeFrames& s) {
  const std::size_t needed = covered_samples(s.frames);
  if (x.size() < needed)
    throw failure("spectral convergence: the signal has " + std::to_string(x.size()) + " samples; " +
                  std::to_string(s.frames) + " frames cover " + std::to_string(needed));
  return spectral_convergence_db(stft_magnitudes(x.first(needed)), s);
}

}  // namespace haptex::render
