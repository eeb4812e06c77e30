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
#include "dataset/window.hpp"
#include "synth/stroke_generator.hpp"
#include "dataset/truth_file.hpp"

namespace haptex::synth {

using dataset::kSampleRateHz;  // every synthetic recording's rate
// White noise per accelerometer axis (m/s^2, standard deviation): a MEMS accelerometer's floor at
// 10 kHz. truth.h5 records it, since the evaluation's noise floor includes it.
inline constexpr double kAccelNoise = 0.02;

struct RecordingIdentity {
  std::string material;
  std::optional<int> texture;
  double friction = 0.3;  // tangential force = friction x normal force
};

// accel: the tool's vibration (m/s^2), one value per stroke sample.
convert::Recording assemble_recording(const RecordingIdentity& identity, const Strokes& strokes,
                                      std::span<const double> accel, std::uint64_t seed);

// Writes recording `index` as HaTT recorded-data XML at path (synth/recorded_data_xml.hpp) and
// returns what truth.h5 keeps of it: the noise-free action it was made from (strokes' speed and
// force, moved out) and the SHA-256 of the file as written, which convert stamps as @source_sha256,
// so the evaluation can find a converted recording's truth.
dataset::TruthRecording write_recording(const std::string& path, int index, const convert::Recording& recording, Strokes&& strokes);

}  // namespace haptex::synth
