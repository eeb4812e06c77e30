#pragma once
// How a procedural material feels through a probe: the tip traces the (tip-smoothed) height profile
// along its path; the profile's second derivative drives a contact resonance whose frequency rises
// with normal force; the response grows with force. Speed maps the surface's spatial spectrum to
// temporal frequency, so spectra move up with speed as real textures do.
#include <cstdint>
#include <span>
#include <vector>

#include "synth/height_field.hpp"
#include "synth/material_families.hpp"

namespace haptex::synth {

inline constexpr double kTipRadiusMm = 1.6;  // HaTT's probe: a 3.175 mm stainless steel hemisphere

class ProbeVibration {
 public:
  // tip_field: the surface smoothed for the tip (smoothed_for_tip).
  ProbeVibration(const HeightField& tip_field, const MaterialSpec& spec);
  ProbeVibration(HeightField&&, const MaterialSpec&) = delete;  // keeps a reference: the field must outlive it

  // Vibration (m/s^2) along a path sampled at fs, with normal force per sample. Noise-free.
  std::vector<double> along_path(std::span<const double> x_mm, std::span<const double> y_mm,
                                 std::span<const double> force_n, double fs) const;

  // The contact resonance at a force (Hz).
  double resonance_hz(double force_n) const;

 private:
  const HeightField& field_;
  MaterialSpec spec_;
};

}  // namespace haptex::synth
