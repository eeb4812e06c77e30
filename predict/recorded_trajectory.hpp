#pragma once
// A recorded stroke as the trajectory render and play read (docs/render.md, "A trajectory to start
// from"): a recording's 20 Hz low-passed normal force and speed, as the model was trained on them, so a
// user can hear a model along a stroke a person actually made before writing trajectories of their own.
#include <cstddef>
#include <string>

#include "dataset/format.hpp"
#include "predict/trajectory.hpp"

namespace haptex::predict {

struct RecordedStretch {
  std::string material;     // material id
  int recording = 0;        // k of /materials/<id>/recordings/<k>
  double start_s = 0;       // from this time in the recording
  double seconds = 0;       // this long; 0: to the recording's end
};

// A recordings or dataset file opened for recorded_trajectory (dataset::open_any: another kind or
// version is refused naming the file).
dataset::OpenedFile open_trajectory_source(const std::string& path);

// Reads the stretch from the file. Throws haptex::Error (bad_input) naming the file and the material
// (listing the file's ids) or the recording (saying how many it has), or a start at or past the
// recording's end. The caller runs qa's layout checks first (apps/trajectory_command.cpp), so the
// recordings are numbered 0..n-1 as the message says.
Trajectory recorded_trajectory(const dataset::OpenedFile& source, const RecordedStretch& stretch);

}  // namespace haptex::predict
