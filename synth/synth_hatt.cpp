#include <algorithm>
#include <filesystem>
#include <map>
#include <mutex>

#include "convert/hatt_model_reader.hpp"
#include "convert/input_limits.hpp"
#include "core/input_file.hpp"
#include "core/error.hpp"
#include "core/naming.hpp"
#include "core/parallel.hpp"
#include "core/text/utf8.hpp"
#include "synth/hatt_recordings.hpp"
#include "synth/photo_press.hpp"
#include "synth/recording_assembly.hpp"
#include "core/random_seeds.hpp"
#include "synth/synth_output.hpp"
#include "synth/synth_runs.hpp"
#include "dataset/truth_file.hpp"

namespace haptex::synth {
namespace fs = std::filesystem;

namespace {

std::vector<fs::path> model_files(const std::string& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw input_error(dir, "", "not a folder", "Point --models at the HaTT models folder");
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("Models_", 0) != 0 || entry.path().extension() != ".xml" || entry.is_directory()) continue;
    require_regular_file(entry.path().string());  // a FIFO or a dangling link is refused by name, not skipped
    files.push_back(entry.path());
  }
  if (files.empty())
    throw input_error(dir, "", "no Models_<Material>.xml files", "Point --models at the HaTT toolkit's models folder");
  std::sort(files.begin(), files.end());
  return files;
}

// A model as rendered and as truth.h5 keeps it: parsed from the very bytes stored, so the
// evaluation's oracle renders the model that made the recordings.
struct ModelFile {
  std::string xml;
  ar::PiecewiseArModel model;
};

// truth.h5 stores the text as a UTF-8 string attribute, which can hold neither other bytes nor NUL.
void check_storable(const std::string& xml, const std::string& file) {
  const std::size_t bad = std::min(text::invalid_utf8_offset(xml), xml.find('\0'));
  if (bad != std::string::npos)
    throw input_error(file, "byte " + std::to_string(bad), xml[bad] == '\0' ? "a NUL byte" : "not UTF-8",
                      "truth.h5 keeps the model's text as UTF-8: save the model file as UTF-8 text");
}

ModelFile load_model(const fs::path& file) {
  const std::vector<char> bytes = convert::read_whole_file(file.string(), convert::kDefaultMaxBytes);
  std::string xml(bytes.begin(), bytes.end());
  check_storable(xml, file.string());
  ar::PiecewiseArModel model(convert::parse_hatt_model(xml, file.string()));
  return {std::move(xml), std::move(model)};
}

// Refuses, before anything is written, a <material> that gives no id or one too long for a file name
// (convert hatt would refuse the set), and two model files of one material (they would write the same files).
void check_unique_materials(const std::vector<ModelFile>& models, const std::vector<fs::path>& files) {
  std::map<std::string, std::string> seen;
  for (std::size_t i = 0; i < models.size(); ++i) {
    const std::string& material = models[i].model.set().material;
    const auto [it, fresh] = seen.emplace(checked_material_id(material, files[i].string(), "<material>"), files[i].string());
    if (!fresh)
      throw input_error(files[i].string(), "<material>", "'" + material + "' is also the material of " + it->second,
                        "Keep one model file per material");
  }
}

// The material's recordings, written to OUT/recordings, and what generated them.
dataset::MaterialTruth write_recordings(const std::string& out, const ModelFile& file, const SynthHattOptions& o) {
  const std::string& material = file.model.set().material;
  dataset::MaterialTruth truth{material, "hatt-model", file.xml, "", std::nullopt, {}};
  for (int k = 0; k < o.recordings; ++k) {
    HattRecording r = render_hatt_recording(file.model, o.seconds, hatt_recording_seed(o.seed, material, k));
    truth.recordings.push_back(write_recording(recording_path(out, material, k), k, r.recording, std::move(r.strokes)));
  }
  return truth;
}

}  // namespace

SynthSummary synth_hatt(const SynthHattOptions& o, const Progress& progress) {
  const std::vector<fs::path> files = model_files(o.models_dir);
  std::vector<ModelFile> models;
  for (const auto& file : files) models.push_back(load_model(file));  // refuse bad files before writing
  check_unique_materials(models, files);
  std::error_code ec;
  if (!o.images_dir.empty() && !fs::is_directory(o.images_dir, ec))
    throw input_error(o.images_dir, "", "not a folder", "Point --images at the folder of <Material>_square.jpg photographs");
  OutputFolder folder(o.out, o.overwrite);
  const std::string out = folder.path();
  const PhotoPressOptions photo;

  SynthSummary summary;
  // In the order of the model files; each material's slot is filled by the thread that renders it.
  dataset::Truth truth{kSampleRateHz, kAccelNoise, std::vector<dataset::MaterialTruth>(models.size())};
  std::mutex mutex;
  std::size_t done = 0;
  folder.fill([&](const std::string&) {
    parallel_for(models.size(), [&](std::size_t i) {
      const std::string& material = models[i].model.set().material;
      truth.materials[i] = write_recordings(out, models[i], o);
      const fs::path image = fs::path(o.images_dir) / (material + "_square.jpg");
      std::error_code ec;
      const bool named = !o.images_dir.empty() && fs::exists(fs::symlink_status(image, ec));
      if (named) require_regular_file(image.string());  // a FIFO or dangling link of that name is refused, not skipped
      const bool has_image = named;
      if (has_image)
        write_photo_presses(image.string(), gelsight_directory(out, material), material,
                            derive_seed(o.seed, name_seed(material_id(material)), 1000), o.provenance, photo);
      std::lock_guard lock(mutex);
      if (!o.images_dir.empty() && !has_image) summary.materials_without_images.push_back(material);
      if (progress) progress(++done, models.size(), material);
    });
    dataset::write_truth_file((fs::path(out) / "truth.h5").string(), truth, o.provenance);
  });
  for (const auto& m : models) summary.materials.push_back(m.model.set().material);
  std::sort(summary.materials_without_images.begin(), summary.materials_without_images.end());
  summary.recordings = models.size() * std::size_t(o.recordings);
  summary.presses = o.images_dir.empty() ? 0 : (models.size() - summary.materials_without_images.size()) * std::size_t(photo.presses);
  folder.commit();
  return summary;
}

}  // namespace haptex::synth
