#pragma once
// Models of the small pipeline (tests/support/small_pipeline.hpp) trained quickly, as a user runs
// haptex train: 4 epochs, latent 8, predictor 16. Trained once per test program, on first use.
#include <string>
#include <vector>

namespace haptex::test {

// The options that make training quick, for tests that run haptex train themselves.
const std::vector<std::string>& quick_train_options();

// haptex train DATASET --split SPLIT -o MODEL with the quick options (and --per-material when asked).
std::vector<std::string> quick_train_args(const std::string& dataset, const std::string& split, const std::string& model,
                                          bool per_material = false);

// The unified or the per-material model of the small pipeline.
const std::string& quick_model(bool per_material = false);

}  // namespace haptex::test
