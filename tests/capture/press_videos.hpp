#pragma once
// Press videos like the ones `haptex synth` writes (FFV1 in Matroska, lossless), made from the fake
// camera's scene: black start-up frames, no contact, then presses rising, holding and releasing.
#include <linux/videodev2.h>

#include <string>
#include <vector>

#include <opencv2/videoio.hpp>

#include "capture/device/fake_scene.hpp"

namespace haptex::capture::fixtures {

// Writes `frames` frames; returns each frame's press depth (0..1).
inline std::vector<double> write_press_video(const std::string& path, const PressSchedule& schedule, int frames,
                                             int width = 160, int height = 120,
                                             int fourcc = cv::VideoWriter::fourcc('F', 'F', 'V', '1')) {
  const FakeScene scene(V4L2_PIX_FMT_MJPEG, width, height, schedule);
  std::vector<cv::Mat> levels;  // [level * 2 + noise]
  for (int level = 0; level <= FakeScene::kDepthLevels; ++level)
    for (int noise = 0; noise < 2; ++noise) levels.push_back(scene.image(level, noise));
  cv::VideoWriter video(path, cv::CAP_FFMPEG, fourcc, 30.0, {width, height});
  std::vector<double> depth;
  for (int i = 0; i < frames; ++i) {
    depth.push_back(scene.depth(std::uint64_t(i)));
    const int level = int(std::lround(depth.back() * FakeScene::kDepthLevels));
    video.write(scene.black(std::uint64_t(i)) ? cv::Mat::zeros(height, width, CV_8UC3) : levels[std::size_t(level * 2 + i % 2)]);
  }
  return depth;
}

}  // namespace haptex::capture::fixtures
