#pragma once
// Renders tool vibration (m/s^2) from a HaTT piecewise AR model along a speed/force trajectory,
// one sample per (speed, force) pair, as the toolkit's haptic loop does: every tick it re-blends
// the model at the current speed and force (HashAndInterp2) and runs one step of the all-pole
// filter with a fresh N(0, var) excitation, keeping the filter's output history across ticks.
#include <cstdint>
#include <span>
#include <vector>

#include "core/ar/ar_filter.hpp"
#include "core/ar/gaussian_noise.hpp"
#include "core/ar/piecewise_model.hpp"

namespace haptex::ar {

class TextureRenderer {
 public:
  // Keeps its own copy of the model; the same seed gives the same samples on the same build.
  TextureRenderer(PiecewiseArModel model, std::uint64_t seed);

  // The next sample at this speed (mm/s) and normal force (N). Cheap: re-blends only when the
  // clamped operating point changed, and never allocates after the first call.
  double next(double speed, double force);

  // One sample per (speed[i], force[i]), continuing from the current state.
  // Throws haptex::Error when the lengths differ.
  std::vector<double> render(std::span<const double> speed, std::span<const double> force);

  // Back to rest with a new seed.
  void reset(std::uint64_t seed);

  // The blended model used for the last sample.
  const BlendedAr& current() const { return blend_; }
  const PiecewiseArModel& model() const { return model_; }

 private:
  PiecewiseArModel model_;
  GaussianNoise noise_;
  AllPoleFilter filter_;
  BlendedAr blend_;
  std::vector<double> work_;
  bool have_blend_ = false;
  double sigma_ = 0.0;
};

// Convenience: a fresh renderer over a whole trajectory.
std::vector<double> render_texture(const PiecewiseArModel& model, std::span<const double> speed,
                                   std::span<const double> force, std::uint64_t seed);

}  // namespace haptex::ar
