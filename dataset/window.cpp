#include "dataset/window.hpp"

namespace haptex::dataset {

std::vector<std::int64_t> window_starts(std::size_t samples, std::size_t stride) {
  std::vector<std::int64_t> starts;
  for (std::size_t t = 0; t + kWindowSamples <= samples; t += stride) starts.push_back(std::int64_t(t));
  return starts;
}

ActionPoint action_point(std::span<const float> action) { return {action[kActionSamples - 1], action[kActionValues - 1]}; }

std::string window_place(std::size_t w, std::string_view material, std::int64_t recording, std::int64_t start) {
  return "/windows[" + std::to_string(w) + "] (" + std::string(material) + ", recording " + std::to_string(recording) +
         ", start " + std::to_string(start) + ")";
}

}  // namespace haptex::dataset
