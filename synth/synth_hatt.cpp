#include <algorithm>
#include <filesystem>
#include <map>
#include <mutex>

#include "convert/hatt_model_reader.hpp"
#include "core/error.hpp"
#include "core/naming.hpp"
#include "core/parallel.hpp"
#include "synth/hatt_recordings.hpp"
#include "synth/photo_press.hpp"
#include "synth/recorded_data_xml.hpp"
#include "core/random_seeds.hpp"
#include "synth/synth_output.hpp"
#include "synth/synth_runs.hpp"

namespace haptex::synth {
namespace fs = std::filesystem;

namespace {

std::vector<fs::path> model_files(const std::string& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw input_error(dir, "", "not a folder", "Point --models at the HaTT models folder");
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_regular_file() && name.rfind("Models_", 0) == 0 && entry.path().extension() == ".xml")
      files.push_back(entry.path());
  }
  if (files.empty())
    throw input_error(dir, "", "no Models_<Material>.xml files", "Point --models at the HaTT toolkit's models folder");
  std::sort(files.begin(), files.end());
  return files;
}

// Refuses, before anything is written, two model files of one material (they would write the same files).
void check_unique_materials(const std::vector<ar::PiecewiseArModel>& models, const std::vector<fs::path>& files) {
  std::map<std::string, std::string> seen;
  for (std::size_t i = 0; i < models.size(); ++i) {
    const auto [it, fresh] = seen.emplace(material_id(models[i].set().material), files[i].string());
    if (!fresh)
      throw input_error(files[i].string(), "<material>", "'" + models[i].set().material + "' is also the material of " + it->second,
                        "Keep one model file per material");
  }
}

}  // namespace

SynthSummary synth_hatt(const SynthHattOptions& o, const Progress& progress) {
  const std::vector<fs::path> files = model_files(o.models_dir);
  std::vector<ar::PiecewiseArModel> models;
  for (const auto& file : files) models.push_back(convert::load_hatt_model(file));  // refuse bad files before writing
  check_unique_materials(models, files);
  std::error_code ec;
  if (!o.images_dir.empty() && !fs::is_directory(o.images_dir, ec))
    throw input_error(o.images_dir, "", "not a folder", "Point --images at the folder of <Material>_square.jpg photographs");
  OutputFolder folder(o.out, o.overwrite);
  const std::string out = folder.path();
  const PhotoPressOptions photo;

  SynthSummary summary;
  std::mutex mutex;
  std::size_t done = 0;
  parallel_for(models.size(), [&](std::size_t i) {
    const std::string& material = models[i].set().material;
    for (int k = 0; k < o.recordings; ++k)
      write_recorded_data_xml(recording_path(out, material, k),
                              render_hatt_recording(models[i], o.seconds, hatt_recording_seed(o.seed, material, k)));
    const fs::path image = fs::path(o.images_dir) / (material + "_square.jpg");
    const bool has_image = !o.images_dir.empty() && fs::is_regular_file(image);
    if (has_image)
      write_photo_presses(image.string(), gelsight_directory(out, material), material,
                          derive_seed(o.seed, name_seed(material_id(material)), 1000), o.provenance, photo);
    std::lock_guard lock(mutex);
    if (!o.images_dir.empty() && !has_image) summary.materials_without_images.push_back(material);
    if (progress) progress(++done, models.size(), material);
  });
  for (const auto& model : models) summary.materials.push_back(model.set().material);
  std::sort(summary.materials_without_images.begin(), summary.materials_without_images.end());
  summary.recordings = models.size() * std::size_t(o.recordings);
  summary.presses = o.images_dir.empty() ? 0 : (models.size() - summary.materials_without_images.size()) * std::size_t(photo.presses);
  folder.commit();
  return summary;
}

}  // namespace haptex::synth
