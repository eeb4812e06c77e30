#pragma once
// The ground truth a predictor can be scored against: for each material, the noise-free expected
// amplitude spectrum (docs/architecture.md, "The model's sample": 100 bins, 10..1000 Hz, of 1000-sample windows) on a grid
// of constant forces and speeds, averaged over 64 windows of straight strokes in many directions and places.
// truth.h5 (dataset/truth_file.hpp) stores the grid with each synthetic material.
#include <cstdint>

#include "synth/probe_vibration.hpp"
#include "synth/stroke_generator.hpp"
#include "dataset/truth_file.hpp"

namespace haptex::synth {

struct TruthOptions {
  int speeds = 10, forces = 8, strokes_per_point = 16;  // x 4 windows each: 64 windows per point
};

dataset::TruthGrid expected_spectra(const ProbeVibration& probe, const StrokeLimits& limits, std::uint64_t seed,
                           const TruthOptions& options = {});

}  // namespace haptex::synth
