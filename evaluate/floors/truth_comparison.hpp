#pragma once
// For synthetic materials (haptex synth materials), the expected spectra are known: truth.h5
// (dataset/truth_file.hpp) holds each material's noise-free spectrum on a speed x force grid
// (HaTT-model materials have none and are skipped). This compares a model's predictions
// there with them, and, for scale, a constant spectrum per material (the truth's own mean over the
// grid: the best any action-blind predictor can do).
#include <string>
#include <vector>

#include "predict/model.hpp"

namespace haptex::evaluate {

struct TruthComparison {
  std::string id;
  std::size_t points = 0;       // grid points inside the model's training force-speed range
  double model = 0;             // mean Euclidean distance of the model's spectra to the truth, m/s^2
  double constant = 0;          // the same for the truth's mean spectrum over those points
  double truth_norm = 0;        // mean Euclidean norm of the true spectra, for scale
};

// Materials of truth.h5 the model knows; unified models use the material's mean training latent,
// per-material models its own network. Materials without a grid (synth hatt's) give no entry, so a
// synth hatt truth.h5 gives an empty list. Throws haptex::Error (bad_input) when read_truth_file
// refuses the file, or when it holds no material of the model.
std::vector<TruthComparison> compare_with_truth(const predict::Model& model, const std::string& truth_path);

// All materials together, each weighted by its points; id empty.
TruthComparison overall(const std::vector<TruthComparison>& materials);

}  // namespace haptex::evaluate
