#pragma once
// A material's surface as a periodic height map: heights (mm) on an n x n grid covering
// period_mm x period_mm. It repeats in x and y, so every (x, y) has a height: the probe's long
// strokes and the GelSight's presses at different places all read the same surface.
#include <cstdint>
#include <string>
#include <vector>

namespace haptex::synth {

struct HeightField {
  int n = 0;
  double period_mm = 0;
  std::vector<float> height_mm;  // row-major: index iy * n + ix, x to the right, y down

  double pixel_mm() const { return period_mm / n; }
  float at(int ix, int iy) const;                 // wraps around
  double sample(double x_mm, double y_mm) const;  // cubic B-spline (C2-smooth), periodic
};

// Periodic structure on top of the random roughness.
enum class Pattern { none, grooves, weave, mesh, dots };

// What makes one material: a shared physical cause for how it looks (GelSight) and how it feels
// (vibration).
struct SurfaceRecipe {
  std::string family;
  double rms_um = 5;             // RMS height of the random roughness
  double correlation_mm = 0.2;   // correlation length of the roughness along its long axis
  double anisotropy = 1;         // long / short correlation length (1: isotropic)
  double angle_rad = 0;          // direction of the long axis
  Pattern pattern = Pattern::none;
  double pattern_period_mm = 1;  // rounded so the pattern repeats exactly within the field
  double pattern_height_um = 0;  // peak-to-valley of the pattern
  double pattern_angle_rad = 0;
};

// Spectral synthesis (Gaussian-correlated random surface, inverse DFT) plus the analytic pattern.
// Deterministic for a seed. n must be a power of two.
HeightField make_height_field(const SurfaceRecipe& recipe, std::uint64_t seed, int n = 1024, double period_mm = 16.0);

// The surface as a spherical probe tip of this radius feels it: fine detail narrower than the tip's
// contact patch is smoothed away (Gaussian low-pass of width ~ the contact radius).
HeightField smoothed_for_tip(const HeightField& field, double tip_radius_mm);

}  // namespace haptex::synth
