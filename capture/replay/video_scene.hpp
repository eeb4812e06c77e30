#pragma once
// A video replayed as a camera films it: each frame decoded (OpenCV's FFmpeg) and encoded the way a
// sensor would send it. Lossy videos (MPEG-4, H.264, MJPG ...) become MJPG, what GelSight-type
// sensors send; lossless ones (FFV1, PNG, HuffYUV, raw) become raw YUYV, so the recorder keeps them
// lossless and scores them with the lossless floors, as `capture extract` does with the same file.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <opencv2/videoio.hpp>

#include "capture/device/camera_scene.hpp"
#include "capture/device/fake_camera.hpp"
#include "media/codecs.hpp"

namespace haptex::capture {

// The one mode a replay of this video offers: MJPG or YUYV at the video's size and frame rate (0 when
// the container does not say). Throws haptex::Error (bad_input) naming the file when it is no video.
FakeMode video_replay_mode(const std::string& path);

class VideoScene : public CameraScene {
 public:
  // Opens the video from its start; `fourcc` is the mode's.
  VideoScene(const std::string& path, std::uint32_t fourcc);
  // Decodes the next frame; nullptr after the last one (or at the first that does not decode, where
  // extraction stops reading too).
  const std::vector<std::uint8_t>* frame(std::uint64_t k) override;

 private:
  std::unique_ptr<media::VideoReader> video_;
  std::uint32_t fourcc_;
  std::vector<std::uint8_t> payload_;
};

// JPEG quality of the MJPG the replay sends: high, so re-encoding changes a frame far less than the
// source's own compression did, and the recorder cuts the presses extraction finds in the video
// (frame for frame on gsrobotics' mini_example, docs/capture.md).
constexpr int kReplayJpegQuality = 95;

}  // namespace haptex::capture
