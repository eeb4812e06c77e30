#pragma once
// `haptex align`: GelSight presses joined with vibration recordings per material, checked, and cut
// into the model's windows (dataset/window.hpp; schemas/hdf5-layout.md "Dataset file").
#include <cstddef>
#include <string>
#include <vector>

#include "align/material_matching.hpp"
#include "core/progress.hpp"
#include "dataset/window.hpp"

namespace haptex::align {

struct AlignOptions {
  std::string recordings, gelsight, output;
  std::size_t stride = dataset::kGridStride;
  std::string names_file;  // optional name map
  bool overwrite = false;
  std::string provenance;
};

struct AlignResult {
  MaterialMatch match;
  std::size_t recordings = 0, presses = 0, windows = 0;
  std::vector<std::string> notes;  // things worth knowing that are not errors
};

// Refuses (bad_input, naming file and object) wrong file kinds, no common material, a material
// joined twice, a recording with another sample rate, units or too short for one window, and presses
// of one material with different image sizes. Writes atomically.
AlignResult align_dataset(const AlignOptions& options, const Progress& progress = {});

}  // namespace haptex::align
