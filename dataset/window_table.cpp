#include "dataset/window_table.hpp"

#include <type_traits>

#include "core/error.hpp"
#include "dataset/layout.hpp"

namespace haptex::dataset {
namespace {

constexpr const char* kRealign = "Run haptex align again to rebuild the dataset";

// A column of `rows` values (width 0) or a (rows, width) matrix; rows unknown: any.
template <typename T>
std::vector<T> column(const h5::Group& windows, const char* name, std::size_t width, std::size_t rows, const std::string& path) {
  if (!windows.has_dataset(name)) throw input_error(path, "/" + std::string(layout::kWindows) + "/" + name, "is missing", kRealign);
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

void expect_attribute(const h5::Group& windows, const char* name, std::size_t value, const std::string& path) {
  const std::int64_t found = windows.has_attr(name) ? windows.attr_int(name) : -1;
  if (found != std::int64_t(value))
    throw input_error(path, windows.object_path() + "/@" + name,
                      found < 0 ? "is missing" : "is " + std::to_string(found) + ", this haptex's windows have " + std::to_string(value),
                      kRealign);
}

}  // namespace

void write_window_table(h5::Group root, const WindowTable& t) {
  h5::Group g = root.create_group(layout::kWindows);
  g.set_attr(layout::kStride, std::int64_t(t.stride));
  g.set_attr(layout::kActionSamplesAttr, std::int64_t(kActionSamples));
  g.set_attr(layout::kWindowSamplesAttr, std::int64_t(kWindowSamples));
  g.set_attr(layout::kActionEndAttr, std::int64_t(kActionEnd));
  g.set_attr(layout::kActionStepAttr, std::int64_t(kActionStep));
  g.write_strings(layout::kWindowMaterials, t.materials);
  g.write(layout::kWindowMaterial, t.material);
  g.write(layout::kWindowRecording, t.recording);
  g.write(layout::kWindowStart, t.start);
  g.write_array<float>(layout::kWindowAction, t.action, {t.size(), kActionValues})
      .set_attr("description", "10 low-passed normal-force samples (N) then 10 low-passed speed samples (mm/s) at start + 50, start + 100, .. start + 500, the window's middle");
  h5::Dataset target = g.write_array<float>(layout::kWindowTarget, t.target, {t.size(), kTargetBins});
  target.set_attr("units", "m/s^2");
  target.set_attr("description", "single-sided amplitude spectrum 2|X_k|/N of accel[start, start + 1000), k = 1..100");
}

std::size_t most_windows(const h5::Group& root, std::size_t stride) {
  std::size_t most = 0;
  if (!root.has_group(layout::kMaterials) || stride == 0) return most;
  const h5::Group materials = root.open_group(layout::kMaterials);
  for (const std::string& id : materials.children()) {
    if (!materials.has_group(id) || !materials.open_group(id).has_group(layout::kRecordings)) continue;
    const h5::Group recordings = materials.open_group(id).open_group(layout::kRecordings);
    for (const std::string& k : recordings.children())
      if (recordings.has_group(k) && recordings.open_group(k).has_dataset(layout::kAccel)) {
        const h5::Shape shape = recordings.open_group(k).open_dataset(layout::kAccel).shape();
        if (!shape.empty()) most += std::size_t(shape[0]) / stride + 1;
      }
  }
  return most;
}

WindowTable read_window_table(const h5::File& file) {
  const std::string& path = file.path();
  const h5::Group root = file.root();
  if (!root.has_group(layout::kWindows)) throw input_error(path, "/" + std::string(layout::kWindows), "is missing", kRealign);
  const h5::Group w = root.open_group(layout::kWindows);
  expect_attribute(w, layout::kActionSamplesAttr, kActionSamples, path);
  expect_attribute(w, layout::kWindowSamplesAttr, kWindowSamples, path);
  expect_attribute(w, layout::kActionEndAttr, kActionEnd, path);
  expect_attribute(w, layout::kActionStepAttr, kActionStep, path);
  WindowTable t;
  if (!w.has_dataset(layout::kWindowMaterials) || w.open_dataset(layout::kWindowMaterials).dtype() != "string")
    throw input_error(path, w.object_path() + "/" + layout::kWindowMaterials, "is missing or not strings", kRealign);
  const h5::Dataset names = w.open_dataset(layout::kWindowMaterials);
  if (names.shape().size() != 1)  // review 18, F9: qa and view refused these, split and train read them flat
    throw input_error(path, names.object_path(), "has shape " + h5::shape_text(names.shape()) + ", expected (materials)", kRealign);
  t.materials = names.read_strings();
  const std::int64_t stride = w.has_attr(layout::kStride) ? w.attr_int(layout::kStride) : 0;
  if (stride <= 0) throw input_error(path, w.object_path() + "/@" + layout::kStride, "is missing or not positive", kRealign);
  t.stride = std::size_t(stride);
  t.start = column<std::int64_t>(w, layout::kWindowStart, 0, std::size_t(-1), path);
  // A dataset's table (a windows file has the same columns and no recordings: haptex windows).
  if (const std::size_t most = most_windows(root, t.stride); root.has_group(layout::kMaterials) && t.size() > most)
    throw input_error(path, w.object_path() + "/" + layout::kWindowStart,
                      "has " + std::to_string(t.size()) + " rows, more than the " + std::to_string(most) + " windows its recordings hold at stride " +
                          std::to_string(t.stride),
                      kRealign);
  t.material = column<std::int32_t>(w, layout::kWindowMaterial, 0, t.size(), path);
  t.recording = column<std::int32_t>(w, layout::kWindowRecording, 0, t.size(), path);
  t.action = column<float>(w, layout::kWindowAction, kActionValues, t.size(), path);
  t.target = column<float>(w, layout::kWindowTarget, kTargetBins, t.size(), path);
  return t;
}

}  // namespace haptex::dataset
