#include "split/dataset_view.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "align/align_dataset.hpp"
#include "align/window_table.hpp"
#include "core/error.hpp"
#include "core/h5/file.hpp"

namespace haptex::split {

namespace {

constexpr const char* kRealign = "Run haptex align again to rebuild the dataset";
constexpr std::size_t kMostRecordings = 100000;  // far above any rig, small enough to index safely

template <typename T>
std::vector<T> column(const h5::Group& windows, const char* name, std::size_t width, std::size_t rows, const std::string& path) {
  const h5::Dataset d = windows.open_dataset(name);
  const std::string kind = std::is_integral_v<T> ? "int" : "float";
  if (d.dtype().rfind(kind, 0) != 0)
    throw input_error(path, d.object_path(), "holds " + d.dtype() + ", expected " + kind + " values", kRealign);
  const h5::Shape shape = d.shape();
  const bool fits = width == 0 ? shape.size() == 1 : shape.size() == 2 && shape[1] == width;
  if (!fits || (rows != std::size_t(-1) && shape[0] != rows))
    throw input_error(path, d.object_path(),
                      "has shape " + h5::shape_text(shape) + ", expected (" + (rows == std::size_t(-1) ? "windows" : std::to_string(rows)) +
                          (width == 0 ? "" : ", " + std::to_string(width)) + ")",
                      kRealign);
  return d.read<T>();
}

// Samples per recording, by recording number; 0 where a number is missing.
std::vector<std::int64_t> recording_lengths(const h5::Group& recordings, const std::string& path) {
  std::vector<std::int64_t> samples;
  for (const std::string& k : recordings.children()) {
    const bool number = !k.empty() && k.size() <= 6 && std::all_of(k.begin(), k.end(), [](unsigned char c) { return c >= '0' && c <= '9'; });
    if (!number || std::stoul(k) >= kMostRecordings)
      throw input_error(path, recordings.object_path() + "/" + k, "is not a recording number (0, 1, 2, ...)", kRealign);
    const std::size_t index = std::stoul(k);
    const h5::Shape shape = recordings.open_group(k).open_dataset("accel").shape();
    if (shape.size() != 1)
      throw input_error(path, recordings.object_path() + "/" + k + "/accel", "is not a 1-D signal", kRealign);
    if (samples.size() <= index) samples.resize(index + 1, 0);
    samples[index] = std::int64_t(shape[0]);
  }
  return samples;
}

}  // namespace

std::vector<MaterialWindows> read_dataset_windows(const std::string& path) {
  const h5::File file = h5::File::open(path);
  const h5::Group root = file.root();
  if (!root.has_attr("haptex_format") || root.attr_string("haptex_format") != align::kDatasetFormat)
    throw input_error(path, "/", "not a dataset file (" + std::string(align::kDatasetFormat) + ")", "Give the file haptex align wrote");
  const h5::Group w = root.open_group("windows");
  const std::vector<std::string> ids = w.open_dataset("materials").read_strings();
  const auto start = column<std::int64_t>(w, "start", 0, std::size_t(-1), path);
  const auto material = column<std::int32_t>(w, "material", 0, start.size(), path);
  const auto recording = column<std::int32_t>(w, "recording", 0, start.size(), path);
  const auto action = column<float>(w, "action", align::kActionValues, start.size(), path);
  const auto target = column<float>(w, "target", align::kTargetBins, start.size(), path);
  constexpr std::size_t kSamples = align::kActionSamples;

  std::vector<MaterialWindows> out(ids.size());
  const h5::Group materials = root.open_group("materials");
  for (std::size_t m = 0; m < ids.size(); ++m) {
    const h5::Group g = materials.open_group(ids[m]);
    out[m].id = ids[m];
    out[m].name = g.has_attr("name") ? g.attr_string("name") : ids[m];
    out[m].recording_samples = recording_lengths(g.open_group("recordings"), path);
    out[m].presses = g.open_group("presses").children().size();
  }
  for (std::size_t i = 0; i < start.size(); ++i) {
    if (material[i] < 0 || std::size_t(material[i]) >= ids.size())
      throw input_error(path, "/windows/material", "window " + std::to_string(i) + " names material " + std::to_string(material[i]) +
                                                       " of " + std::to_string(ids.size()), kRealign);
    MaterialWindows& m = out[std::size_t(material[i])];
    const std::string place = align::window_place(i, m.id, recording[i], start[i]);
    const bool recorded = recording[i] >= 0 && std::size_t(recording[i]) < m.recording_samples.size() &&
                          m.recording_samples[std::size_t(recording[i])] > 0;
    if (!recorded) throw input_error(path, place, "the dataset has no such recording of " + m.id, kRealign);
    if (align::window_first_sample(start[i]) < 0 || align::window_end_sample(start[i]) > m.recording_samples[std::size_t(recording[i])])
      throw input_error(path, place, "the window runs outside its recording's " +
                                         std::to_string(m.recording_samples[std::size_t(recording[i])]) + " samples", kRealign);
    for (const auto& [values, width, what] : {std::tuple{&action, align::kActionValues, "action"}, std::tuple{&target, align::kTargetBins, "target"}}) {
      const auto row = values->begin() + std::ptrdiff_t(i * width);
      const auto bad = std::find_if(row, row + std::ptrdiff_t(width), [](float v) { return !std::isfinite(v); });
      if (bad != row + std::ptrdiff_t(width))
        throw input_error(path, place, std::string(what) + " value " + std::to_string(bad - row) + " is " + std::to_string(*bad),
                          "The recording holds NaN or infinite samples: haptex qa on the recordings file finds them; fix or drop "
                          "that recording, then convert and align again");
    }
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
