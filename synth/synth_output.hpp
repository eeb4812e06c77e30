#pragma once
// The folder `haptex synth` writes, laid out for the real pipeline:
//   OUT/recordings/<material_id>_<k>.xml          HaTT recorded-data XML (haptex convert hatt OUT/recordings)
//   OUT/gelsight/<Material name>/press_<j>/...    press videos as PNG sequences (haptex capture extract OUT/gelsight)
//   OUT/gelsight/<Material name>/press_<j>.json   the true peak frame and contact interval
//   OUT/truth.h5, OUT/materials.json              (synth materials) ground truth and recipes
#include <string>

namespace haptex::synth {

// Creates OUT and its subfolders. Refuses (bad input) a non-empty OUT unless overwrite.
void prepare_output_directory(const std::string& out, bool overwrite);

std::string recording_path(const std::string& out, const std::string& material, int index);
std::string gelsight_directory(const std::string& out, const std::string& material);

}  // namespace haptex::synth
