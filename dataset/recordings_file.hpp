#pragma once
// The recordings file (schemas/hdf5-layout.md, "Recordings file"), writer and reader side by side:
// /materials/<material_id>/recordings/<k>/ with DFT321 acceleration, raw axes, raw and 20 Hz
// zero-phase low-passed normal force and speed, tangential force and position where present, the
// source and its preprocessing as attributes. What convert computes before it is stored is
// convert/preprocess.hpp's; a dataset file holds copies of these recordings, read the same way.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/h5/node.hpp"

namespace haptex::dataset {

// The format's low-pass of force and speed (schemas/hdf5-layout.md): convert applies it, and qa's
// filter.stated checks that a recording states it.
inline constexpr int kLowpassOrder = 4;
inline constexpr double kLowpassCutoffHz = 20.0;

// How the low-passed signals were made, stated in each recording's attributes.
struct LowpassStated {
  std::string filter;
  int order = 0;
  double cutoff_hz = 0;
  std::string method, description;  // description: how a dataset's own description says it
};

// How the three acceleration axes were reduced to one.
struct AccelReductionStated {
  std::string method;
  std::int64_t window = 0, hop = 0;
};

// One recording as stored, every signal one float32 per sample (accel_xyz and position: x, y, z per
// sample, interleaved).
struct RecordingToWrite {
  std::string material;
  std::optional<int> texture;  // HaTT texture number
  double sample_rate_hz = 0;
  std::string accel_units, force_units, speed_units, position_units;
  std::string source_path, source_sha256;
  std::map<std::string, double> source_numbers;  // more attributes the source states, by their layout names
  std::map<std::string, std::string> source_texts;
  LowpassStated lowpass;
  AccelReductionStated accel_reduction;
  std::vector<float> accel, accel_xyz, force_normal, speed, force_normal_lp, speed_lp, force_tangential, position;

  std::size_t samples() const { return accel.size(); }
};

struct WrittenRecording {
  std::string material_id;
  int index = 0;
};

// Appends the recording as the next index of its material (0, 1, ...). Names that differ only in
// case, spaces, '_' or '-' are one material (as `haptex align` joins them); the first spelling is
// kept. Throws haptex::Error (bad_input) naming the source when the name makes no id.
WrittenRecording write_recording(h5::Group root, const RecordingToWrite& recording);

// The three signals of a recording the model's windows are cut from: DFT321 acceleration, low-passed
// normal force and low-passed speed, from a recordings file or a dataset's copy of it.
struct RecordingSignals {
  std::vector<float> accel, force_lp, speed_lp;  // m/s^2, N, mm/s; one value per 10 kHz sample
  std::string source_sha256;                     // the recording's source file hash ("" when absent)
};

// Reads /materials/{m}/recordings/{k}. Throws haptex::Error (bad_input) naming the file and the
// recording when a signal is missing, in other units than the layout's, of another length than the
// others, or sampled at another rate than 10 kHz; the fixes say to resample or convert again.
RecordingSignals read_recording_signals(const h5::Group& recording);

}  // namespace haptex::dataset
