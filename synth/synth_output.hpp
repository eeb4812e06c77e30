#pragma once
// The folder `haptex synth` writes, laid out for the real pipeline:
//   OUT/recordings/<material_id>_<k>.xml.gz       HaTT recorded-data XML, gzip (haptex convert hatt OUT/recordings)
//   OUT/gelsight/<Material name>/press_<j>.avi     press videos, MJPG (haptex capture extract OUT/gelsight)
//   OUT/gelsight/<Material name>/press_<j>.json   the true peak frame and contact interval
//   OUT/truth.h5                                  what generated each recording (dataset/truth_file.hpp)
//   OUT/materials.json                            (synth materials) the recipes
#include <string>

#include "core/partial_directory.hpp"

namespace haptex::synth {

// Everything is written into OUT.partial/ (core/partial_directory.hpp) and renamed to OUT by
// commit(): a failure half way leaves OUT as it was. A non-empty OUT is refused (bad input) unless
// overwrite, which replaces it whole on commit, and only while it holds nothing but what haptex
// wrote (core/owned_folder.hpp).
class OutputFolder {
 public:
  OutputFolder(const std::string& out, bool overwrite);

  const std::string& path() const { return partial_.path(); }  // where to write until commit()
  // PartialDirectory::fill: errors name the output folder, not its temporary name.
  void fill(const std::function<void(const std::string& dir)>& write) const { partial_.fill(write); }
  void commit() { partial_.commit(); }

 private:
  PartialDirectory partial_;
};

std::string recording_path(const std::string& out, const std::string& material, int index);
std::string gelsight_directory(const std::string& out, const std::string& material);

}  // namespace haptex::synth
