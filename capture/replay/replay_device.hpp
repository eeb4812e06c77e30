#pragma once
// `--device replay:FILE[,KEY=VALUE,...]`: a video or a press file played as a camera (librealsense's
// record and playback), through the fake camera and so through the same kernel seam as a sensor: live
// segmentation, drop accounting and press files run on real sensor content.
//
// FILE is everything after "replay:" up to the first comma that starts a known key, so names with
// commas, spaces and quotes need no escaping; only a name containing ",KEY" for one of the keys below
// cannot be given (rename or link it). Files ending in .h5 or .hdf5 are press files (as for `capture
// extract`), anything else is a video.
//
// Keys: fps (the file's rate; required when the file does not say), lockstep (as fast as the recorder
// takes frames, instead of at the file's rate), speed (times the file's rate), and the fake camera's
// faults: drop, error, corrupt (percent of frames), disconnect=FRAMES, stall=FRAME:MS, seed.
//
// The device offers one mode: the file's frame size, at its rate, in MJPG (lossy videos, re-encoded;
// MJPG press files, the stored bytes) or YUYV (lossless videos, PNG press files). After the file's
// last frame the stream ends the way a finite V4L2 stream does (V4L2_BUF_FLAG_LAST, then EPIPE), and
// the take ends "source ended" with every frame kept.
#include <string>

#include "capture/device/fake_device_spec.hpp"

namespace haptex::capture {

bool is_replay_device(const std::string& device);
// Reads the file's size, format and rate. Throws haptex::Error (bad_input) naming the file or the key,
// and the fix: a missing, unreadable or non-video file, an unknown key, a bad value.
FakeDevice parse_replay_device(const std::string& device);

}  // namespace haptex::capture
