#pragma once
// What the fake camera films: a gel with a smooth colour gradient and marker dots, pressed again and
// again by a round indenter (idle, rise, hold, release, gap), after a few black start-up frames like
// real UVC sensors send. Payloads are encoded once per press depth and reused, so the fake camera
// can serve 3280 x 2464 MJPG at 25 fps with almost no CPU of its own.
#include <cstdint>
#include <memory>
#include <vector>

#include <opencv2/core.hpp>

#include "capture/device/camera_scene.hpp"

namespace haptex::capture {

struct PressSchedule {
  int black_frames = 5;   // sent right after stream start, as real sensors do
  int idle_frames = 45;   // no contact before the first press
  int rise_frames = 8, hold_frames = 10, release_frames = 8;
  int gap_frames = 30;    // no contact between presses
  int presses = -1;       // -1: press forever
};

class FakeScene : public CameraScene {
 public:
  FakeScene(std::uint32_t fourcc, int width, int height, const PressSchedule& schedule, std::uint64_t seed = 1);
  ~FakeScene() override;

  // Never ends: payload(k) for every k.
  const std::vector<std::uint8_t>* frame(std::uint64_t k) override { return &payload(k); }

  // Press depth 0..1 of scene frame k (0 during black and no-contact frames).
  double depth(std::uint64_t frame) const;
  bool black(std::uint64_t frame) const { return frame < std::uint64_t(schedule_.black_frames); }
  // The encoded frame (MJPG or YUYV bytes). Two noise patterns alternate, so consecutive
  // no-contact frames differ like a real sensor's.
  const std::vector<std::uint8_t>& payload(std::uint64_t frame) const;
  // The image behind the payloads of one depth level (0..kDepthLevels) and noise pattern (0, 1), BGR.
  // Renders it again: meant for tests, not for streaming.
  cv::Mat image(int level, int noise_pattern) const;
  // Frames from the first press's start to the end of its release.
  std::uint64_t first_press_frame() const { return std::uint64_t(schedule_.black_frames + schedule_.idle_frames); }
  std::uint64_t press_period() const;

  static constexpr int kDepthLevels = 8;  // payloads per noise pattern above depth 0

 private:
  std::vector<std::uint8_t> encode(const cv::Mat& bgr) const;
  std::uint32_t fourcc_;
  int width_, height_;
  std::uint64_t seed_;
  PressSchedule schedule_;
  // Every payload, rendered when first asked for (index level * 2 + noise pattern; the black one
  // last), so STREAMON returns at once and the recorder's loop, which reads Ctrl-C, runs between
  // renderings (review 5: the default fake spent seconds rendering all up front, deaf to signals).
  // The float images they are made from (hundreds of MB at 3280 x 2464) are freed once all are made.
  struct Images;
  mutable std::unique_ptr<Images> images_;
  mutable std::vector<std::vector<std::uint8_t>> payloads_;
  mutable std::size_t rendered_ = 0;
};

// One frame of the scene, BGR: the gel pressed to depth level 0..kDepthLevels, with noise pattern 0 or 1.
// Renders from scratch; FakeScene keeps the encoded payloads instead.
cv::Mat render_gel(int width, int height, int level, int noise_pattern, std::uint64_t seed = 1);

// Packs a BGR image as YUYV (4:2:2) the way UVC cameras send it: BT.601 in video range. The width must be even.
std::vector<std::uint8_t> bgr_to_yuyv(const cv::Mat& bgr);

}  // namespace haptex::capture
