#pragma once
// The two generators behind `haptex synth`, deterministic for a seed (byte-identical outputs on the
// same build), writing the folder of synth/synth_output.hpp.
#include <cstdint>
#include <string>
#include <vector>

#include "core/progress.hpp"

namespace haptex::synth {

struct SynthSummary {
  std::vector<std::string> materials;
  std::size_t recordings = 0, presses = 0;
  std::vector<std::string> materials_without_images;  // synth hatt --images: no <Material>_square.jpg
};

struct SynthHattOptions {
  std::string models_dir, images_dir, out;  // images_dir may be empty: no presses
  int recordings = 2;
  double seconds = 10;
  std::uint64_t seed = 0;
  bool overwrite = false;
  std::string provenance;
};

// Every Models_<Material>.xml in models_dir: recordings rendered from the piecewise AR model along
// free-hand strokes; with images_dir, five press videos cut from <Material>_square.jpg.
SynthSummary synth_hatt(const SynthHattOptions& options, const Progress& progress = {});

struct SynthMaterialsOptions {
  int count = 8;  // 8: the default demo set, one material per family
  std::string out;
  int recordings = 2, presses = 5;
  double seconds = 10;
  int width = 960, height = 720;
  std::uint64_t seed = 0;
  bool overwrite = false;
  std::string provenance;
};

// Procedural materials: height field -> GelSight press videos, probe recordings, truth spectra.
SynthSummary synth_materials(const SynthMaterialsOptions& options, const Progress& progress = {});

}  // namespace haptex::synth
