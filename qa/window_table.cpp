#include "qa/window_table.hpp"

#include <string_view>

#include "core/error.hpp"
#include "dataset/layout.hpp"
#include "dataset/window_table.hpp"

namespace haptex::qa {

namespace layout = dataset::layout;
namespace {

template <typename T>
bool read_column(const h5::Group& windows, const char* name, std::vector<T>& out, std::string& problem) {
  if (!windows.has_dataset(name)) {
    problem = "/windows/" + std::string(name) + " is missing";
    return false;
  }
  const h5::Dataset d = windows.open_dataset(name);
  if (d.shape().size() != 1 || d.dtype() == "string") {
    problem = "/windows/" + std::string(name) + " is not a column of numbers";
    return false;
  }
  out = d.read<T>();
  return true;
}

bool read_matrix(const h5::Group& windows, const char* name, std::size_t rows, std::vector<float>& out,
                 std::size_t& width) {
  if (!windows.has_dataset(name)) return false;
  const h5::Dataset d = windows.open_dataset(name);
  const h5::Shape shape = d.shape();
  if (shape.size() != 2 || shape[0] != rows || d.dtype().rfind("float", 0) != 0) return false;
  width = shape[1];
  out = d.read<float>();
  return true;
}

}  // namespace

std::optional<WindowTable> load_window_table(const h5::Group& root, std::string& problem) {
  if (!root.has_group(layout::kWindows)) {
    problem = "/windows is missing";
    return std::nullopt;
  }
  const h5::Group windows = root.open_group(layout::kWindows);
  WindowTable t;
  if (!windows.has_dataset(layout::kMaterials) || windows.open_dataset(layout::kMaterials).dtype() != "string") {
    problem = "/windows/materials is missing or not strings";
    return std::nullopt;
  }
  t.materials = windows.open_dataset(layout::kMaterials).read_strings();
  if (!read_column(windows, "material", t.material, problem) || !read_column(windows, "recording", t.recording, problem) ||
      !read_column(windows, "start", t.start, problem))
    return std::nullopt;
  if (t.material.size() != t.start.size() || t.recording.size() != t.start.size()) {
    problem = "/windows/material, recording and start differ in length";
    return std::nullopt;
  }
  const auto stride = windows.try_attr<std::int64_t>(layout::kStride), action = windows.try_attr<std::int64_t>(layout::kActionSamplesAttr),
             window = windows.try_attr<std::int64_t>(layout::kWindowSamplesAttr), action_end = windows.try_attr<std::int64_t>(layout::kActionEndAttr),
             action_step = windows.try_attr<std::int64_t>(layout::kActionStepAttr);
  // Review 18, F11: the attribute at fault is named.
  const std::pair<const char*, const std::optional<std::int64_t>&> attributes[] = {
      {layout::kStride, stride}, {layout::kActionSamplesAttr, action}, {layout::kWindowSamplesAttr, window},
      {layout::kActionStepAttr, action_step}, {layout::kActionEndAttr, action_end}};
  for (const auto& [name, value] : attributes) {
    const bool may_be_zero = std::string_view(name) == layout::kActionEndAttr;  // the window's first sample
    if (!value || *value < (may_be_zero ? 0 : 1)) {
      problem = "/windows/@" + std::string(name) + " is missing or not one " + (may_be_zero ? "non-negative" : "positive") + " integer";
      return std::nullopt;
    }
  }
  if (*action > *window || *action_step > *window || (*action - 1) > *action_end / *action_step || *action_end >= *window) {
    problem = "/windows' action_samples, action_step, window_samples and action_end do not fit together (action_end: the "
              "action's last sample inside the window, its first action_step (action_samples - 1) before it)";
    return std::nullopt;
  }
  t.stride = std::size_t(*stride);
  if (const std::size_t most = dataset::most_windows(root, t.stride); t.size() > most) {
    problem = "/windows has " + std::to_string(t.size()) + " rows, more than the " + std::to_string(most) + " windows its recordings hold at stride " +
              std::to_string(t.stride);
    return std::nullopt;
  }
  t.action_samples = *action;
  t.window_samples = *window;
  t.action_end = *action_end;
  t.action_step = *action_step;
  if (!read_matrix(windows, "action", t.size(), t.action, t.action_width)) t.action.clear(), t.action_width = 0;
  if (!read_matrix(windows, "target", t.size(), t.target, t.target_width)) t.target.clear(), t.target_width = 0;
  return t;
}

std::optional<std::int64_t> recording_samples(const h5::Group& root, const std::string& material, std::int32_t recording) {
  if (material.empty() || material.find('/') != std::string::npos || recording < 0 || !root.has_group(layout::kMaterials) ||
      !root.open_group(layout::kMaterials).has_group(material))
    return std::nullopt;
  const h5::Group m = root.open_group(layout::kMaterials).open_group(material);
  if (!m.has_group(layout::kRecordings) || !m.open_group(layout::kRecordings).has_group(std::to_string(recording))) return std::nullopt;
  return m.open_group(layout::kRecordings).open_group(std::to_string(recording)).try_attr<std::int64_t>(layout::kSamples);
}

}  // namespace haptex::qa
