#pragma once
// `--device fake[:KEY=VALUE,...]`: the fake camera as a device, to try the recorder without a sensor
// and to measure it. Keys: size=WxH (3280x2464), format=MJPG|YUYV (MJPG), fps (25 at 3280x2464, else
// 30), presses (-1: forever), drop, error, corrupt (percent of frames), disconnect=FRAMES,
// stall=FRAME:MS (repeatable), speed (times real time), lockstep (no clock: as fast as the host
// takes frames), seed, metadata (open the sensor's metadata node instead).
#include <optional>
#include <string>

#include "capture/device/fake_camera.hpp"

namespace haptex::capture {

struct FakeDevice {
  FakeCameraConfig config;
  std::string node;  // the path to open on the fake
};

bool is_fake_device(const std::string& device);
// Throws haptex::Error (bad_input) naming the key and what is expected.
FakeDevice parse_fake_device(const std::string& device);

}  // namespace haptex::capture
