#include "align/align_dataset.hpp"

#include "align/window_table.hpp"
#include "core/error.hpp"
#include "core/h5/atomic_file.hpp"
#include "core/sha256.hpp"
#include "dataset/channel_order.hpp"
#include "dataset/format.hpp"
#include "dataset/layout.hpp"
#include "qa/integrity.hpp"

namespace haptex::align {
namespace {

using namespace dataset::layout;

std::vector<NamedMaterial> materials_of(const h5::Group& root, const std::string& collection) {
  std::vector<NamedMaterial> list;
  if (!root.has_group(kMaterials)) return list;
  const h5::Group materials = root.open_group(kMaterials);
  for (const std::string& id : materials.children()) {
    const h5::Group m = materials.open_group(id);
    if (m.has_group(collection)) list.push_back({id, m.has_attr(kName) ? m.attr_string(kName) : id});
  }
  return list;
}

// One recording's signals, after checking what the windows rely on.
WindowSource read_source(const h5::Group& recording, int material, int index) {
  WindowSource s{material, index, dataset::read_recording_signals(recording)};
  if (s.signals.accel.size() < dataset::kWindowSamples)
    throw input_error(recording.file(), recording.object_path(), "only " + std::to_string(s.signals.accel.size()) + " samples",
                      "A recording needs at least " + std::to_string(dataset::kWindowSamples) + " samples for one window");
  return s;
}

// All presses of a material must be the same size: the texture encoder sees one image shape. Their
// channel order is copied with them and must be one train and predict can read.
h5::Shape check_press_sizes(const h5::Group& presses) {
  h5::Shape shape;
  for (const std::string& j : presses.children()) {
    const h5::Group press = presses.open_group(j);
    dataset::read_channel_order(press, kPeak);
    const h5::Shape size = {hsize_t(press.attr_int(kHeight)), hsize_t(press.attr_int(kWidth)), 3};
    if (shape.empty()) shape = size;
    else if (size != shape)
      throw input_error(press.file(), press.object_path(), "image size differs from the material's other presses",
                        "Capture all presses of a material with one sensor and frame size");
  }
  return shape;
}

}  // namespace

AlignResult align_dataset(const AlignOptions& o, const Progress& progress) {
  if (o.stride < 1) throw input_error("--stride", "", "must be at least 1", "Pass --stride 100 (10 ms)");
  const h5::File recordings_file = dataset::open_checked(o.recordings, dataset::Kind::recordings),
                 gelsight_file = dataset::open_checked(o.gelsight, dataset::Kind::gelsight);
  const h5::Group recordings_root = recordings_file.root(), gelsight_root = gelsight_file.root();
  qa::require_integrity(recordings_root, dataset::Kind::recordings);
  qa::require_integrity(gelsight_root, dataset::Kind::gelsight);
  AlignResult result;
  result.match = match_materials(materials_of(recordings_root, kRecordings), materials_of(gelsight_root, kPresses),
                                 o.names_file.empty() ? std::map<std::string, std::string>{} : load_name_map(o.names_file),
                                 o.names_file.empty() ? o.gelsight : o.names_file);  // the file whose names joined them
  if (result.match.pairs.empty())
    throw input_error(o.gelsight, "/" + std::string(kMaterials), "no material is in both files", "Check the names, or join them with --names map.json");

  std::vector<WindowSource> signals;
  std::vector<std::string> ids;
  std::vector<h5::Shape> press_shapes;
  for (const MaterialPair& pair : result.match.pairs) {
    const h5::Group recs = recordings_root.open_group(kMaterials).open_group(pair.recordings.id).open_group(kRecordings);
    for (const std::string& k : recs.children()) signals.push_back(read_source(recs.open_group(k), int(ids.size()), std::stoi(k)));
    press_shapes.push_back(check_press_sizes(gelsight_root.open_group(kMaterials).open_group(pair.gelsight.id).open_group(kPresses)));
    ids.push_back(pair.id);
  }
  for (std::size_t i = 1; i < press_shapes.size(); ++i)
    if (press_shapes[i] != press_shapes[0]) {
      result.notes.push_back("presses of different materials have different image sizes (e.g. " + ids[0] + " and " +
                             ids[i] + "); the texture encoder resizes them");
      break;
    }
  if (progress) progress(0, 2, "windows");
  dataset::WindowTable windows = build_windows(signals, o.stride);
  windows.materials = ids;

  h5::AtomicFile out(o.output, o.overwrite, dataset::format_name(dataset::Kind::dataset));
  h5::Group root = out.root();
  dataset::stamp(root, dataset::Kind::dataset, o.provenance);
  root.set_attr(kRecordingsFile, o.recordings);
  root.set_attr(kRecordingsSha256, sha256_file(o.recordings));
  root.set_attr(kGelsightFile, o.gelsight);
  root.set_attr(kGelsightSha256, sha256_file(o.gelsight));
  h5::Group materials = root.create_group(kMaterials);
  h5::CopiedObjects copied_recordings, copied_presses;
  for (const MaterialPair& pair : result.match.pairs) {
    h5::Group m = materials.create_group(pair.id);
    m.set_attr(kName, pair.recordings.name);
    m.set_attr(kRecordingsName, pair.recordings.name);
    m.set_attr(kGelsightName, pair.gelsight.name);
    m.copy_from(recordings_root.open_group(kMaterials).open_group(pair.recordings.id), kRecordings, kRecordings,
                copied_recordings);
    m.copy_from(gelsight_root.open_group(kMaterials).open_group(pair.gelsight.id), kPresses, kPresses, copied_presses);
    result.presses += m.open_group(kPresses).children().size();
  }
  if (progress) progress(1, 2, "writing");
  dataset::write_window_table(root, windows);
  out.commit();
  if (progress) progress(2, 2, "");
  result.recordings = signals.size();
  result.windows = windows.size();
  return result;
}

}  // namespace haptex::align
