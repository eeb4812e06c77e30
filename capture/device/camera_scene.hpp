#pragma once
// What a FakeCamera films: the payload of each frame its sensor makes, already encoded in the granted
// format (MJPG or YUYV bytes). The synthetic gel (fake_scene.hpp) never ends; a replayed file
// (capture/replay/) ends after its last frame, and the camera then ends the stream the way V4L2 does.
#include <cstdint>
#include <vector>

namespace haptex::capture {

class CameraScene {
 public:
  virtual ~CameraScene() = default;
  // The payload of frame k (0 = the first after STREAMON), or nullptr once the scene has ended. The
  // camera asks for every frame once and in order, including frames it then loses, so a scene may
  // read its source sequentially. The bytes stay valid until the next call.
  virtual const std::vector<std::uint8_t>* frame(std::uint64_t k) = 0;
};

}  // namespace haptex::capture
