#pragma once
// A press file replayed as the sensor sent it: MJPG frames ("jpeg") are the stored bytes exactly, never
// re-encoded (unless the file states its frames hold B, G, R: those are decoded, put back in order and
// re-encoded at quality 95, so the replayed take is RGB as haptex writes it); raw YUYV frames, stored as
// lossless PNG, become YUYV again. A stored frame that was
// cut off is sent cut off again, so the recorder counts it corrupt as it did the first time.
#include <cstdint>
#include <string>
#include <vector>

#include "capture/device/camera_scene.hpp"
#include "capture/device/fake_camera.hpp"
#include "dataset/press_file.hpp"
#include "dataset/channel_order.hpp"

namespace haptex::capture {

// MJPG or YUYV (what the sensor sent) at the file's frame size and the rate its driver granted.
// Throws haptex::Error (bad_input) naming the file and object when it is not a press file.
FakeMode press_file_replay_mode(const std::string& path);

class PressFileScene : public CameraScene {
 public:
  explicit PressFileScene(const std::string& path);
  const std::vector<std::uint8_t>* frame(std::uint64_t k) override;  // nullptr after the last

 private:
  dataset::PressFile frames_;
  dataset::ChannelOrder order_;
  std::vector<std::uint8_t> payload_;
};

}  // namespace haptex::capture
