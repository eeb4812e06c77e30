#pragma once
// An in-memory training problem whose answer is known: each material's "images" are noisy copies of
// its own descriptor centre, and its spectra a resonance whose frequency rises with speed and whose
// level grows with force and speed, times multiplicative noise (as real 100 ms spectra scatter).
#include <cstdint>

#include "predict/training_data.hpp"

namespace haptex::test {

struct SyntheticSpec {
  int materials = 4, windows = 600, train_images = 40;
  double noise = 0.15;  // relative spread of each spectrum bin
  std::uint64_t seed = 7;
};

predict::TrainingData synthetic_problem(const SyntheticSpec& spec = {});

// The noise-free spectrum of material m at (force, speed): what a perfect model predicts.
std::vector<float> synthetic_truth(int material, double force, double speed);

}  // namespace haptex::test
