#pragma once
// truth.h5: what generated each synthetic recording (schemas/hdf5-layout.md, "Truth file"), so the
// evaluation can compute the best any predictor could score (docs/evaluate.md, "The noise floor").
// `haptex synth hatt` and `haptex synth materials` write it; `haptex evaluate --truth` reads it.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace haptex::dataset {


// A material's noise-free expected amplitude spectrum (100 bins, 10..1000 Hz, of 1000-sample
// windows; the vibration before sensor noise) on a grid of constant speeds and forces.
struct TruthGrid {
  std::vector<double> speeds_mm_s, forces_n;  // ascending
  std::vector<double> spectra;                // speeds x forces x 100, row-major

  const double* spectrum(std::size_t speed, std::size_t force) const {
    return spectra.data() + (speed * forces_n.size() + force) * 100;
  }
};

// One recording as generated: the noise-free action the vibration was rendered along.
struct TruthRecording {
  int index = 0;              // k of recording_<k> (synth/synth_output.hpp)
  std::string source_sha256;  // SHA-256 of the written recording file: convert's @source_sha256
  std::vector<double> speed_mm_s, force_n;  // one value per sample, before sensor ripple and noise
};

struct MaterialTruth {
  std::string name;
  std::string generator;    // "hatt-model" (model_xml) or "synth-material" (recipe_json, grid)
  std::string model_xml;    // hatt-model: the HaTT model file's content, byte for byte
  std::string recipe_json;  // synth-material: the material's recipe (as in OUT/materials.json)
  std::optional<TruthGrid> grid;
  std::vector<TruthRecording> recordings;
};

struct Truth {
  double sample_rate_hz = 10000;
  double accel_noise_m_s2 = 0;  // white sensor noise per accelerometer axis (standard deviation)
  std::vector<MaterialTruth> materials;

  const MaterialTruth* find(const std::string& material_id) const;  // by core/naming's material_id
};

// Atomic (temporary file, fsync, rename). source: the provenance stamped on the root.
void write_truth_file(const std::string& path, const Truth& truth, const std::string& source);

// Throws haptex::Error (bad_input) naming the file, the object and the fix: not HDF5, another
// format (truth/1 files are refused with "run haptex synth again"), a missing or mistyped member,
// shapes that disagree, non-finite or negative values, an unknown generator.
Truth read_truth_file(const std::string& path);

}  // namespace haptex::dataset
