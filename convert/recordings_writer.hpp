#pragma once
// Writes recordings into a recordings file (schemas/hdf5-layout.md):
// /materials/<material_id>/recordings/<k>/ with DFT321 acceleration, raw axes, raw and 20 Hz
// zero-phase low-passed normal force and speed, tangential force and position where present.
#include <string>

#include "convert/recording.hpp"
#include "core/h5/node.hpp"

namespace haptex::convert {

inline constexpr int kLowpassOrder = 4;
inline constexpr double kLowpassCutoffHz = 20.0;

struct WrittenRecording {
  std::string material_id;
  int index = 0;
};

// Appends the recording as the next index of its material (0, 1, ...).
WrittenRecording write_recording(h5::Group root, const Recording& recording);

}  // namespace haptex::convert
