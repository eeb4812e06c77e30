#pragma once
// What the split needs from a dataset file: each material's windows (recording, start, action
// point) and recording lengths, and its press count.
#include <cstdint>
#include <string>
#include <vector>

namespace haptex::split {

struct MaterialWindows {
  std::string id, name;
  std::vector<std::int64_t> recording_samples;  // by recording number
  std::vector<std::size_t> row;                 // per window: its row in /windows
  std::vector<std::int32_t> recording;          // per window
  std::vector<std::int64_t> start;              // per window
  std::vector<float> speed, force;              // per window: its action point, the newest action sample (dataset::action_point)
  std::size_t presses = 0;
};

// Throws haptex::Error (bad_input) when the file is not a dataset file.
std::vector<MaterialWindows> read_dataset_windows(const std::string& dataset_path);

}  // namespace haptex::split
