#pragma once
// What convert computes from a recording before it is stored (docs/convert.md; schemas/hdf5-layout.md,
// "Recordings file"): the three axes of acceleration reduced to one with DFT321, and normal force and
// speed low-passed at 20 Hz, zero phase, for the model's actions. The file itself is
// dataset/recordings_file.hpp's.
#include "convert/recording.hpp"
#include "dataset/recordings_file.hpp"

namespace haptex::convert {

// The recording as the recordings file stores it: every signal as float32 (24 bits of mantissa is
// beyond any accelerometer's or force sensor's resolution and halves the files; all computation
// happens in double before), the derived ones computed, the source and its units named.
dataset::RecordingToWrite preprocess(const Recording& recording);

}  // namespace haptex::convert
