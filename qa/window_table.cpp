#include "qa/window_table.hpp"

#include <utility>
#include <variant>

#include "dataset/layout.hpp"
#include "dataset/window_table.hpp"

namespace haptex::qa {

namespace layout = dataset::layout;

std::optional<WindowTable> load_window_table(const h5::Group& root, std::string& problem) {
  auto read = dataset::read_stated_window_table(root);
  if (const auto* found = std::get_if<dataset::WindowTableProblem>(&read)) {
    problem = found->text();
    return std::nullopt;
  }
  WindowTable t{std::move(std::get<dataset::StatedWindowTable>(read))};
  if (t.action_samples > t.window_samples || t.action_step > t.window_samples || (t.action_samples - 1) > t.action_end / t.action_step ||
      t.action_end >= t.window_samples) {
    problem = "/windows' action_samples, action_step, window_samples and action_end do not fit together (action_end: the "
              "action's last sample inside the window, its first action_step (action_samples - 1) before it)";
    return std::nullopt;
  }
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
