#pragma once
// `--device fake[:KEY=VALUE,...]`: the fake camera as a device, to try the recorder without a sensor
// and to measure it. Keys: size=WxH (3280x2464), format=MJPG|YUYV (MJPG), fps (25 at 3280x2464, else
// 30), presses (-1: forever), drop, error, corrupt (percent of frames), disconnect=FRAMES,
// stall=FRAME:MS (repeatable), speed (times real time), lockstep (no clock: as fast as the host
// takes frames), seed, metadata (open the sensor's metadata node instead).
//
// The keys for timing and faults (drop to seed) are every fake camera's: `--device replay:FILE,...`
// (capture/replay/replay_device.hpp) takes them too, through DeviceKeys.
#include <optional>
#include <string>

#include "capture/device/fake_camera.hpp"

namespace haptex::capture {

struct FakeDevice {
  FakeCameraConfig config;
  std::string node;  // the path to open on the fake: the --device string itself
  // What it sends was compressed across frames before (a replayed MPEG-4 or H.264 video): its
  // no-contact frames repeat each other's artefacts, so the recorder calibrates its thresholds on the
  // frames after the reference (RecorderOptions::calibration_frames).
  bool inter_frame = false;
  std::string source_file;  // the replayed file (empty for the fake camera): an input of the take
};

bool is_fake_device(const std::string& device);
// Throws haptex::Error (bad_input) naming the key and what is expected.
FakeDevice parse_fake_device(const std::string& device);

// The KEY=VALUE items of a --device string for a fake camera. Refusals name the device and the key,
// and show `usage` (the keys this kind of device takes) as the fix.
class DeviceKeys {
 public:
  DeviceKeys(std::string device, std::string usage) : device_(std::move(device)), usage_(std::move(usage)) {}
  const std::string& device() const { return device_; }
  [[noreturn]] void refuse(const std::string& key, const std::string& what) const;
  // The KEY=VALUE items of a comma-separated list, in order. A key given twice is refused (the last
  // would silently win), except `stall`, which adds a stall each time.
  std::vector<std::pair<std::string, std::string>> items(const std::string& list) const;
  double number(const std::string& key, const std::string& text) const;  // decimal, 0 to 1e12
  std::uint64_t count(const std::string& key, const std::string& text) const;  // whole, 0 to 1e12 (frames, a seed)
  // A key that is a flag (lockstep, metadata) given a value is refused, not read as the flag.
  void flag(const std::string& key, const std::string& value) const;
  double percent(const std::string& key, const std::string& text) const;  // 0 to 100
  // The stream's timing and faults: drop, error, corrupt, disconnect, stall, speed, lockstep, seed.
  // Returns false when `key` is none of them.
  bool apply_stream_key(FakeCameraConfig& config, const std::string& key, const std::string& value) const;
  // Refuses (naming fps and speed) a real-time stream whose frames come slower than a press file's
  // lowest rate, dataset::kLowestFps: fps 1 at speed 0.3 ended every take as a stalled sensor, exit 1
  // and no press (review 26, F2).
  void require_recordable_rate(const FakeCameraConfig& config, double fps) const;

 private:
  std::string device_, usage_;
};

}  // namespace haptex::capture
