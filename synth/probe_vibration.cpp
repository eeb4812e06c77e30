#include "synth/probe_vibration.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.hpp"

namespace haptex::synth {
namespace {

constexpr double kReferenceForce = 1.0;  // N
constexpr double kGain = 0.1;            // tip/handle mass ratio: how much of the trace's motion reaches the handle

}  // namespace

ProbeVibration::ProbeVibration(const HeightField& tip_field, const MaterialSpec& spec) : field_(tip_field), spec_(spec) {}

double ProbeVibration::resonance_hz(double force_n) const {
  // Hertzian contact: stiffness grows as F^(1/3), so the resonance sqrt(k/m) as F^(1/6).
  return spec_.resonance_hz * std::pow(std::max(force_n, 0.05) / kReferenceForce, 1.0 / 6.0);
}

std::vector<double> ProbeVibration::along_path(std::span<const double> x_mm, std::span<const double> y_mm,
                                               std::span<const double> force_n, double fs) const {
  const std::size_t n = x_mm.size();
  if (y_mm.size() != n || force_n.size() != n) throw failure("ProbeVibration: path channels differ in length");
  std::vector<double> height(n);
  for (std::size_t i = 0; i < n; ++i) height[i] = field_.sample(x_mm[i], y_mm[i]);
  std::vector<double> out(n, 0.0);
  double y1 = 0, y2 = 0;
  for (std::size_t i = 1; i + 1 < n; ++i) {
    // The tip's vertical acceleration following the profile (mm -> m).
    const double trace = (height[i + 1] - 2 * height[i] + height[i - 1]) * fs * fs * 1e-3;
    // Two-pole resonator at the contact resonance, unit gain at DC, retuned every sample.
    const double w = 2 * std::numbers::pi * resonance_hz(force_n[i]) / fs;
    const double r = std::exp(-spec_.damping * w);
    const double a1 = 2 * r * std::cos(w), a2 = -r * r;
    const double y = (1 - a1 - a2) * trace + a1 * y1 + a2 * y2;
    y2 = y1;
    y1 = y;
    out[i] = kGain * std::sqrt(std::max(force_n[i], 0.0) / kReferenceForce) * y;
  }
  return out;
}

}  // namespace haptex::synth
