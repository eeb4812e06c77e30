#include "align/align_dataset.hpp"

#include <cmath>

#include "align/window_table.hpp"
#include "core/error.hpp"
#include "core/h5/atomic_file.hpp"
#include "core/sha256.hpp"

namespace haptex::align {
namespace {

constexpr double kSampleRateHz = 10000;

h5::Group open_kind(const h5::File& file, const std::string& format, const std::string& made_by) {
  h5::Group root = file.root();
  const std::string found = root.has_attr("haptex_format") ? root.attr_string("haptex_format") : "";
  if (found != format)
    throw input_error(file.path(), "/", "is a '" + (found.empty() ? "non-haptex" : found) + "' file, not " + format,
                      "Give the file " + made_by + " wrote");
  return root;
}

std::vector<NamedMaterial> materials_of(const h5::Group& root, const std::string& collection) {
  std::vector<NamedMaterial> list;
  if (!root.has_group("materials")) return list;
  const h5::Group materials = root.open_group("materials");
  for (const std::string& id : materials.children()) {
    const h5::Group m = materials.open_group(id);
    if (m.has_group(collection)) list.push_back({id, m.has_attr("name") ? m.attr_string("name") : id});
  }
  return list;
}

void expect_units(const h5::Group& recording, const char* dataset, const char* units) {
  const h5::Dataset d = recording.open_dataset(dataset);
  const std::string found = d.has_attr("units") ? d.attr_string("units") : "";
  if (found != units)
    throw input_error(d.file(), d.object_path(), "units are '" + found + "', expected '" + units + "'",
                      "Convert the recordings again with haptex convert");
}

// One recording's signals, after checking what the windows rely on.
RecordingSignals read_recording(const h5::Group& recording, int material, int index) {
  const double rate = recording.attr_double("sample_rate_hz");
  if (std::abs(rate - kSampleRateHz) > 1e-6)
    throw input_error(recording.file(), recording.object_path(), "sample rate " + std::to_string(rate) + " Hz, not 10000",
                      "Resample to 10 kHz and convert again");
  expect_units(recording, "accel", "m/s^2");
  expect_units(recording, "force_normal_lp", "N");
  expect_units(recording, "speed_lp", "mm/s");
  RecordingSignals s{material, index, recording.open_dataset("accel").read<float>(),
                     recording.open_dataset("force_normal_lp").read<float>(),
                     recording.open_dataset("speed_lp").read<float>()};
  if (s.accel.size() != s.force_lp.size() || s.accel.size() != s.speed_lp.size())
    throw input_error(recording.file(), recording.object_path(), "accel, force_normal_lp and speed_lp differ in length",
                      "Convert the recordings again with haptex convert");
  if (s.accel.size() < kWindowSamples)
    throw input_error(recording.file(), recording.object_path(), "only " + std::to_string(s.accel.size()) + " samples",
                      "A recording needs at least " + std::to_string(kWindowSamples) + " samples for one window");
  return s;
}

// All presses of a material must be the same size: the texture encoder sees one image shape.
h5::Shape check_press_sizes(const h5::Group& presses) {
  h5::Shape shape;
  for (const std::string& j : presses.children()) {
    const h5::Dataset peak = presses.open_group(j).open_dataset("peak");
    if (shape.empty()) shape = peak.shape();
    else if (peak.shape() != shape)
      throw input_error(peak.file(), peak.object_path(), "image size differs from the material's other presses",
                        "Capture all presses of a material with one sensor and frame size");
  }
  return shape;
}

void write_windows(h5::Group root, const WindowTable& t, const std::vector<std::string>& ids, std::size_t stride) {
  h5::Group g = root.create_group("windows");
  g.set_attr("stride", std::int64_t(stride));
  g.set_attr("action_samples", std::int64_t(kActionSamples));
  g.set_attr("window_samples", std::int64_t(kWindowSamples));
  g.set_attr("action_end", std::int64_t(kActionEnd));
  g.write_strings("materials", ids);
  g.write("material", t.material);
  g.write("recording", t.recording);
  g.write("start", t.start);
  g.write_array<float>("action", t.action, {t.size(), kActionValues})
      .set_attr("description", "10 low-passed normal-force samples (N) then 10 low-passed speed samples (mm/s) ending at start + 500, the window's middle");
  h5::Dataset target = g.write_array<float>("target", t.target, {t.size(), kTargetBins});
  target.set_attr("units", "m/s^2");
  target.set_attr("description", "single-sided amplitude spectrum 2|X_k|/N of accel[start, start + 1000), k = 1..100");
}

}  // namespace

AlignResult align_dataset(const AlignOptions& o, const Progress& progress) {
  if (o.stride < 1) throw input_error("--stride", "", "must be at least 1", "Pass --stride 100 (10 ms)");
  const h5::File recordings_file = h5::File::open(o.recordings), gelsight_file = h5::File::open(o.gelsight);
  const h5::Group recordings_root = open_kind(recordings_file, "recordings/1", "haptex convert");
  const h5::Group gelsight_root = open_kind(gelsight_file, "gelsight/1", "haptex capture extract");
  AlignResult result;
  result.match = match_materials(materials_of(recordings_root, "recordings"), materials_of(gelsight_root, "presses"),
                                 o.names_file.empty() ? std::map<std::string, std::string>{} : load_name_map(o.names_file),
                                 o.names_file);
  if (result.match.pairs.empty())
    throw input_error(o.gelsight, "/materials", "no material is in both files", "Check the names, or join them with --names map.json");

  std::vector<RecordingSignals> signals;
  std::vector<std::string> ids;
  std::vector<h5::Shape> press_shapes;
  for (const MaterialPair& pair : result.match.pairs) {
    const h5::Group recs = recordings_root.open_group("materials").open_group(pair.recordings.id).open_group("recordings");
    for (const std::string& k : recs.children())
      signals.push_back(read_recording(recs.open_group(k), int(ids.size()), std::stoi(k)));
    press_shapes.push_back(check_press_sizes(gelsight_root.open_group("materials").open_group(pair.gelsight.id).open_group("presses")));
    ids.push_back(pair.id);
  }
  for (std::size_t i = 1; i < press_shapes.size(); ++i)
    if (press_shapes[i] != press_shapes[0]) {
      result.notes.push_back("presses of different materials have different image sizes (e.g. " + ids[0] + " and " +
                             ids[i] + "); the texture encoder resizes them");
      break;
    }
  if (progress) progress(0, 2, "windows");
  const WindowTable windows = build_windows(signals, o.stride);

  h5::AtomicFile out(o.output, o.overwrite);
  h5::Group root = out.root();
  h5::stamp_root(root, kDatasetFormat, o.provenance);
  root.set_attr("recordings_file", o.recordings);
  root.set_attr("recordings_sha256", sha256_file(o.recordings));
  root.set_attr("gelsight_file", o.gelsight);
  root.set_attr("gelsight_sha256", sha256_file(o.gelsight));
  h5::Group materials = root.create_group("materials");
  for (const MaterialPair& pair : result.match.pairs) {
    h5::Group m = materials.create_group(pair.id);
    m.set_attr("name", pair.recordings.name);
    m.set_attr("recordings_name", pair.recordings.name);
    m.set_attr("gelsight_name", pair.gelsight.name);
    m.copy_from(recordings_root.open_group("materials").open_group(pair.recordings.id), "recordings", "recordings");
    m.copy_from(gelsight_root.open_group("materials").open_group(pair.gelsight.id), "presses", "presses");
    result.presses += m.open_group("presses").children().size();
  }
  if (progress) progress(1, 2, "writing");
  write_windows(root, windows, ids, o.stride);
  out.commit();
  if (progress) progress(2, 2, "");
  result.recordings = signals.size();
  result.windows = windows.size();
  return result;
}

}  // namespace haptex::align
