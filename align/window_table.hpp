#pragma once
// Cutting the model's windows (dataset/window.hpp) from the recordings of a dataset.
#include <cstddef>
#include <vector>

#include "dataset/recordings_file.hpp"
#include "dataset/window_table.hpp"

namespace haptex::align {

// One recording's signals, with the material (index into the dataset's ids) and recording number
// its windows carry.
struct WindowSource {
  int material = 0, recording = 0;
  dataset::RecordingSignals signals;
};

// Every recording's windows on all cores, in the order of `sources` then start: starts every
// `stride` samples, the action ending at each window's middle, the target spectrum of its samples.
dataset::WindowTable build_windows(const std::vector<WindowSource>& sources, std::size_t stride);

}  // namespace haptex::align
