#pragma once
// The ground truth a predictor can be scored against: for each material, the noise-free expected
// amplitude spectrum (DESIGN.md section 3: 100 bins, 10..1000 Hz, of 1000-sample windows) on a grid
// of constant forces and speeds, averaged over 64 windows of straight strokes in many directions and places.
#include <cstdint>
#include <string>
#include <vector>

#include "synth/probe_vibration.hpp"
#include "synth/stroke_generator.hpp"

namespace haptex::synth {

struct TruthGrid {
  std::vector<double> speeds_mm_s, forces_n;
  std::vector<double> spectra;  // speeds x forces x 100, row-major

  const double* spectrum(std::size_t speed, std::size_t force) const {
    return spectra.data() + (speed * forces_n.size() + force) * 100;
  }
};

struct TruthOptions {
  int speeds = 10, forces = 8, strokes_per_point = 16;  // x 4 windows each: 64 windows per point
};

TruthGrid expected_spectra(const ProbeVibration& probe, const StrokeLimits& limits, std::uint64_t seed,
                           const TruthOptions& options = {});

struct MaterialTruth {
  std::string name;
  TruthGrid grid;
};

inline constexpr const char* kTruthFormat = "truth/1";
// truth.h5 (schemas/hdf5-layout.md): /materials/<id>/spectrum (speeds x forces x 100), speeds, forces.
void write_truth_file(const std::string& path, const std::vector<MaterialTruth>& materials, const std::string& source);

}  // namespace haptex::synth
