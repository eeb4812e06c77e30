#include "split/dataset_view.hpp"

#include "align/align_dataset.hpp"
#include "align/window_table.hpp"
#include "core/error.hpp"
#include "core/h5/file.hpp"

namespace haptex::split {

std::vector<MaterialWindows> read_dataset_windows(const std::string& path) {
  const h5::File file = h5::File::open(path);
  const h5::Group root = file.root();
  if (!root.has_attr("haptex_format") || root.attr_string("haptex_format") != align::kDatasetFormat)
    throw input_error(path, "/", "not a dataset file (dataset/1)", "Give the file haptex align wrote");
  const h5::Group w = root.open_group("windows");
  const std::vector<std::string> ids = w.open_dataset("materials").read_strings();
  const auto material = w.open_dataset("material").read<std::int32_t>();
  const auto recording = w.open_dataset("recording").read<std::int32_t>();
  const auto start = w.open_dataset("start").read<std::int64_t>();
  const auto action = w.open_dataset("action").read<float>();
  constexpr std::size_t kSamples = align::kActionSamples;

  std::vector<MaterialWindows> out(ids.size());
  const h5::Group materials = root.open_group("materials");
  for (std::size_t m = 0; m < ids.size(); ++m) {
    const h5::Group g = materials.open_group(ids[m]);
    out[m].id = ids[m];
    out[m].name = g.has_attr("name") ? g.attr_string("name") : ids[m];
    const h5::Group recs = g.open_group("recordings");
    for (const std::string& k : recs.children()) {
      const std::size_t index = std::stoul(k);
      if (out[m].recording_samples.size() <= index) out[m].recording_samples.resize(index + 1, 0);
      out[m].recording_samples[index] = recs.open_group(k).open_dataset("accel").shape().at(0);
    }
    out[m].presses = g.open_group("presses").children().size();
  }
  for (std::size_t i = 0; i < start.size(); ++i) {
    if (material[i] < 0 || std::size_t(material[i]) >= ids.size())
      throw input_error(path, "/windows/material", "window " + std::to_string(i) + " names no material", "Run haptex align again");
    MaterialWindows& m = out[std::size_t(material[i])];
    float force = 0, speed = 0;
    for (std::size_t k = 0; k < kSamples; ++k) {
      force += action[i * 2 * kSamples + k] / float(kSamples);
      speed += action[i * 2 * kSamples + kSamples + k] / float(kSamples);
    }
    m.row.push_back(i);
    m.recording.push_back(recording[i]);
    m.start.push_back(start[i]);
    m.force.push_back(force);
    m.speed.push_back(speed);
  }
  return out;
}

}  // namespace haptex::split
