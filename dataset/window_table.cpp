#include "dataset/window_table.hpp"

#include <optional>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>

#include "core/error.hpp"
#include "dataset/layout.hpp"

namespace haptex::dataset {
namespace {

constexpr const char* kRealign = "Run haptex align again to rebuild the dataset";

std::string object(const char* name) { return "/" + std::string(layout::kWindows) + "/" + name; }

std::string expected_shape(std::size_t rows, std::size_t width) {
  return "expected (" + (rows == std::size_t(-1) ? std::string("windows") : std::to_string(rows)) +
         (width == 0 ? "" : ", " + std::to_string(width)) + ")";
}

// A column of `rows` values (width 0) or a (rows, width) matrix of T's kind (rows unknown: any), or
// what is wrong with it.
template <typename T>
std::optional<WindowTableProblem> read_column(const h5::Group& windows, const char* name, std::size_t width, std::size_t rows,
                                              std::vector<T>& out) {
  if (!windows.has_dataset(name)) return WindowTableProblem{object(name), "is missing"};
  const h5::Dataset d = windows.open_dataset(name);
  const std::string kind = std::is_integral_v<T> ? "int" : "float";
  if (d.dtype().rfind(kind, 0) != 0) return WindowTableProblem{object(name), "holds " + d.dtype() + ", expected " + kind + " values"};
  const h5::Shape shape = d.shape();
  const bool fits = width == 0 ? shape.size() == 1 : shape.size() == 2 && shape[1] == width;
  if (!fits || (rows != std::size_t(-1) && shape[0] != rows))
    return WindowTableProblem{object(name), "has shape " + h5::shape_text(shape) + ", " + expected_shape(rows, width)};
  out = d.read<T>();
  return std::nullopt;
}

// A (rows, any width) float matrix, or nothing (width 0): qa reports its width against the contract.
void read_any_width(const h5::Group& windows, const char* name, std::size_t rows, std::vector<float>& out, std::size_t& width) {
  if (!windows.has_dataset(name)) return;
  const h5::Dataset d = windows.open_dataset(name);
  const h5::Shape shape = d.shape();
  if (shape.size() != 2 || shape[0] != rows || shape[1] == 0 || d.dtype().rfind("float", 0) != 0) return;
  width = shape[1];
  out = d.read<float>();
}

// The contract's attributes as stored: one positive integer each (action_end, the window's first
// sample at the least, may be 0); stride too.
std::optional<WindowTableProblem> read_attributes(const h5::Group& windows, StatedWindowTable& t) {
  std::int64_t stride = 0;
  const std::pair<const char*, std::int64_t*> attributes[] = {
      {layout::kStride, &stride}, {layout::kActionSamplesAttr, &t.action_samples}, {layout::kWindowSamplesAttr, &t.window_samples},
      {layout::kActionStepAttr, &t.action_step}, {layout::kActionEndAttr, &t.action_end}};
  for (const auto& [name, value] : attributes) {
    const bool may_be_zero = std::string_view(name) == layout::kActionEndAttr;
    const std::optional<std::int64_t> stated = windows.try_attr<std::int64_t>(name);
    // Review 18, F11: the attribute at fault is named.
    if (!stated || *stated < (may_be_zero ? 0 : 1))
      return WindowTableProblem{windows.object_path() + "/@" + name,
                                std::string("is missing or not one ") + (may_be_zero ? "non-negative" : "positive") + " integer"};
    *value = *stated;
  }
  t.stride = std::size_t(stride);
  return std::nullopt;
}

std::optional<WindowTableProblem> read_materials(const h5::Group& windows, StatedWindowTable& t) {
  if (!windows.has_dataset(layout::kWindowMaterials) || windows.open_dataset(layout::kWindowMaterials).dtype() != "string")
    return WindowTableProblem{object(layout::kWindowMaterials), "is missing or not strings"};
  const h5::Dataset names = windows.open_dataset(layout::kWindowMaterials);
  if (names.shape().size() != 1)  // review 18, F9: split and train read a (1, 2) table flat
    return WindowTableProblem{names.object_path(), "has shape " + h5::shape_text(names.shape()) + ", expected (materials)"};
  t.materials = names.read_strings();
  return std::nullopt;
}

// The integer columns, of one length, no longer than the recordings allow (a windows file has no
// recordings: haptex windows).
std::optional<WindowTableProblem> read_rows(const h5::Group& root, const h5::Group& windows, StatedWindowTable& t) {
  if (auto problem = read_column<std::int64_t>(windows, layout::kWindowStart, 0, std::size_t(-1), t.start)) return problem;
  if (const std::size_t most = most_windows(root, t.stride); root.has_group(layout::kMaterials) && t.size() > most)
    return WindowTableProblem{object(layout::kWindowStart), "has " + std::to_string(t.size()) + " rows, more than the " + std::to_string(most) +
                                                                " windows its recordings hold at stride " + std::to_string(t.stride)};
  if (auto problem = read_column<std::int32_t>(windows, layout::kWindowMaterial, 0, t.size(), t.material)) return problem;
  return read_column<std::int32_t>(windows, layout::kWindowRecording, 0, t.size(), t.recording);
}

// An attribute of the table that differs from this haptex's contract, refused naming it.
void expect_attribute(const h5::Group& windows, const char* name, std::int64_t stated, std::size_t value, const std::string& path) {
  if (stated != std::int64_t(value))
    throw input_error(path, windows.object_path() + "/@" + name,
                      "is " + std::to_string(stated) + ", this haptex's windows have " + std::to_string(value), kRealign);
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

std::variant<StatedWindowTable, WindowTableProblem> read_stated_window_table(const h5::Group& root) {
  if (!root.has_group(layout::kWindows)) return WindowTableProblem{"/" + std::string(layout::kWindows), "is missing"};
  const h5::Group windows = root.open_group(layout::kWindows);
  StatedWindowTable t;
  if (auto problem = read_attributes(windows, t)) return *problem;
  if (auto problem = read_materials(windows, t)) return *problem;
  if (auto problem = read_rows(root, windows, t)) return *problem;
  read_any_width(windows, layout::kWindowAction, t.size(), t.action, t.action_width);
  read_any_width(windows, layout::kWindowTarget, t.size(), t.target, t.target_width);
  return t;
}

WindowTable read_window_table(const h5::File& file) {
  const std::string& path = file.path();
  auto read = read_stated_window_table(file.root());
  if (const auto* problem = std::get_if<WindowTableProblem>(&read)) throw input_error(path, problem->where, problem->what, kRealign);
  StatedWindowTable& t = std::get<StatedWindowTable>(read);
  const h5::Group windows = file.root().open_group(layout::kWindows);
  expect_attribute(windows, layout::kActionSamplesAttr, t.action_samples, kActionSamples, path);
  expect_attribute(windows, layout::kWindowSamplesAttr, t.window_samples, kWindowSamples, path);
  expect_attribute(windows, layout::kActionEndAttr, t.action_end, kActionEnd, path);
  expect_attribute(windows, layout::kActionStepAttr, t.action_step, kActionStep, path);
  const std::tuple<const char*, std::size_t, std::size_t> matrices[] = {{layout::kWindowAction, t.action_width, kActionValues},
                                                                        {layout::kWindowTarget, t.target_width, kTargetBins}};
  for (const auto& [name, stated, width] : matrices)
    if (stated != width) {  // missing, of another type or shape: said precisely
      std::vector<float> unused;
      const auto problem = read_column<float>(windows, name, width, t.size(), unused);
      throw input_error(path, problem ? problem->where : object(name), problem ? problem->what : "is unreadable", kRealign);
    }
  return std::move(static_cast<WindowTable&>(t));
}

}  // namespace haptex::dataset
