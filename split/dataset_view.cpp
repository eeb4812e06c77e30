#include "split/dataset_view.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/h5/file.hpp"
#include "core/naming.hpp"
#include "dataset/format.hpp"
#include "dataset/layout.hpp"
#include "dataset/window_table.hpp"

namespace haptex::split {

namespace {

using namespace dataset::layout;
constexpr const char* kRealign = "Run haptex align again to rebuild the dataset";
constexpr std::size_t kMostRecordings = 100000;  // far above any rig, small enough to index safely

// Samples per recording, by recording number; 0 where a number is missing.
std::vector<std::int64_t> recording_lengths(const h5::Group& recordings, const std::string& path) {
  std::vector<std::int64_t> samples;
  for (const std::string& k : recordings.children()) {
    const bool number = !k.empty() && k.size() <= 6 && std::all_of(k.begin(), k.end(), [](unsigned char c) { return c >= '0' && c <= '9'; });
    if (!number || std::stoul(k) >= kMostRecordings)
      throw input_error(path, recordings.object_path() + "/" + k, "is not a recording number (0, 1, 2, ...)", kRealign);
    const std::size_t index = std::stoul(k);
    const h5::Shape shape = recordings.open_group(k).open_dataset(kAccel).shape();
    if (shape.size() != 1)
      throw input_error(path, recordings.object_path() + "/" + k + "/" + kAccel, "is not a 1-D signal", kRealign);
    if (samples.size() <= index) samples.resize(index + 1, 0);
    samples[index] = std::int64_t(shape[0]);
  }
  return samples;
}

}  // namespace

std::vector<MaterialWindows> read_dataset_windows(const std::string& path) {
  const h5::File file = dataset::open_checked(path, dataset::Kind::dataset);
  const h5::Group root = file.root();
  const dataset::WindowTable t = dataset::read_window_table(file);
  const std::vector<std::string>& ids = t.materials;
  std::vector<MaterialWindows> out(ids.size());
  const h5::Group materials = root.open_group(kMaterials);
  for (const std::string& id : ids) checked_material_id(id, path, "/windows/materials");  // file names are made of them
  for (std::size_t m = 0; m < ids.size(); ++m) {
    const h5::Group g = materials.open_group(ids[m]);
    out[m].id = ids[m];
    out[m].name = g.has_attr(kName) ? g.attr_string(kName) : ids[m];
    out[m].recording_samples = recording_lengths(g.open_group(kRecordings), path);
    out[m].presses = g.open_group(kPresses).children().size();
  }
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t.material[i] < 0 || std::size_t(t.material[i]) >= ids.size())
      throw input_error(path, "/windows/material", "window " + std::to_string(i) + " names material " + std::to_string(t.material[i]) +
                                                       " of " + std::to_string(ids.size()), kRealign);
    MaterialWindows& m = out[std::size_t(t.material[i])];
    const std::int32_t recording = t.recording[i];
    const std::string place = dataset::window_place(i, m.id, recording, t.start[i]);
    const bool recorded = recording >= 0 && std::size_t(recording) < m.recording_samples.size() && m.recording_samples[std::size_t(recording)] > 0;
    if (!recorded) throw input_error(path, place, "the dataset has no such recording of " + m.id, kRealign);
    if (dataset::window_first_sample(t.start[i]) < 0 || dataset::window_end_sample(t.start[i]) > m.recording_samples[std::size_t(recording)])
      throw input_error(path, place, "the window runs outside its recording's " + std::to_string(m.recording_samples[std::size_t(recording)]) + " samples",
                        kRealign);
    for (const auto& [values, what] : {std::pair{t.action_of(i), "action"}, std::pair{t.target_of(i), "target"}}) {
      const auto bad = std::find_if(values.begin(), values.end(), [](float v) { return !std::isfinite(v); });
      if (bad != values.end())
        throw input_error(path, place, std::string(what) + " value " + std::to_string(bad - values.begin()) + " is " + std::to_string(*bad),
                          "The recording holds NaN or infinite samples: haptex qa on the recordings file finds them; fix or drop "
                          "that recording, then convert and align again");
    }
    const dataset::ActionPoint point = dataset::action_point(t.action_of(i));
    m.row.push_back(i);
    m.recording.push_back(recording);
    m.start.push_back(t.start[i]);
    m.force.push_back(point.force);
    m.speed.push_back(point.speed);
  }
  return out;
}

}  // namespace haptex::split
