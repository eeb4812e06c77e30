#pragma once
// What turns a hand motion and the vibration it causes into a recording as a rig measures it:
// the vibration spread over three accelerometer axes along a slowly turning direction (so DFT321
// matters) with sensor noise, and force and speed sensors that pick up a little texture ripple
// above 20 Hz (so the action low-pass filter has real work to do).
#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "convert/recording.hpp"
#include "synth/stroke_generator.hpp"

namespace haptex::synth {

struct RecordingIdentity {
  std::string material;
  std::optional<int> texture;
  double friction = 0.3;  // tangential force = friction x normal force
};

// accel: the tool's vibration (m/s^2), one value per stroke sample.
convert::Recording assemble_recording(const RecordingIdentity& identity, const Strokes& strokes,
                                      std::span<const double> accel, std::uint64_t seed);

}  // namespace haptex::synth
