#pragma once
// The folder `haptex synth` writes, laid out for the real pipeline:
//   OUT/recordings/<material_id>_<k>.xml          HaTT recorded-data XML (haptex convert hatt OUT/recordings)
//   OUT/gelsight/<Material name>/press_<j>/...    press videos as PNG sequences (haptex capture extract OUT/gelsight)
//   OUT/gelsight/<Material name>/press_<j>.json   the true peak frame and contact interval
//   OUT/truth.h5                                  what generated each recording (synth/truth_file.hpp)
//   OUT/materials.json                            (synth materials) the recipes
#include <string>

namespace haptex::synth {

// Everything is written into OUT.partial/ and renamed to OUT by commit(), so a failure half way
// leaves no OUT (and removes OUT.partial). A non-empty OUT is refused (bad input) unless overwrite,
// which replaces it whole on commit (nothing of an earlier run survives next to the new one), and
// only while it holds nothing but what haptex wrote (core/owned_folder.hpp): a foreign file is refused.
class OutputFolder {
 public:
  OutputFolder(std::string out, bool overwrite);
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  const std::string& path() const { return staging_; }  // where to write until commit()
  void commit();

 private:
  std::string out_, staging_;
  bool committed_ = false;
};

std::string recording_path(const std::string& out, const std::string& material, int index);
std::string gelsight_directory(const std::string& out, const std::string& material);

}  // namespace haptex::synth
