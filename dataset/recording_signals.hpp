#pragma once
// The three signals of a recording the model's windows are cut from (schemas/hdf5-layout.md,
// "Recordings file"): DFT321 acceleration, low-passed normal force and low-passed speed, from a
// recordings file or a dataset's copy of it.
#include <string>
#include <vector>

#include "core/h5/node.hpp"

namespace haptex::dataset {

struct RecordingSignals {
  std::vector<float> accel, force_lp, speed_lp;  // m/s^2, N, mm/s; one value per 10 kHz sample
  std::string source_sha256;                     // the recording's source file hash ("" when absent)
};

// Reads /materials/{m}/recordings/{k}. Throws haptex::Error (bad_input) naming the file and the
// recording when a signal is missing, in other units than the layout's, of another length than the
// others, or sampled at another rate than 10 kHz; the fixes say to resample or convert again.
RecordingSignals read_recording_signals(const h5::Group& recording);

}  // namespace haptex::dataset
