#pragma once
// Small fake cameras for the capture tests: 320 x 240 frames keep every test fast while still going
// through the reduced-size JPEG decoding (2x) the recorder uses at full size.
#include <linux/videodev2.h>

#include "capture/device/fake_camera.hpp"

namespace haptex::capture::fixtures {

inline PressSchedule quick_presses(int presses = -1) {
  PressSchedule s;
  s.black_frames = 5;
  s.idle_frames = 25;
  s.rise_frames = 4;
  s.hold_frames = 4;
  s.release_frames = 4;
  s.gap_frames = 16;
  s.presses = presses;
  return s;
}

inline FakeCameraConfig small_camera(std::uint32_t fourcc = V4L2_PIX_FMT_MJPEG, std::uint32_t width = 320,
                                     std::uint32_t height = 240, double fps = 30) {
  FakeCameraConfig c;
  c.modes = {{fourcc, width, height, {fps}}};
  c.scene = quick_presses();
  return c;
}

}  // namespace haptex::capture::fixtures
