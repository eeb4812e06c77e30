#include "capture/replay/video_scene.hpp"

#include <linux/videodev2.h>


#include "capture/device/fake_scene.hpp"
#include "capture/storage/video_file.hpp"
#include "media/codecs.hpp"

namespace haptex::capture {

FakeMode video_replay_mode(const std::string& path) {
  const VideoProbe probe = probe_video_file(path);
  FakeMode mode;
  mode.fourcc = probe.lossless ? V4L2_PIX_FMT_YUYV : V4L2_PIX_FMT_MJPEG;
  mode.width = std::uint32_t(probe.size.width);
  mode.height = std::uint32_t(probe.size.height);
  mode.fps = {probe.fps};
  return mode;
}

VideoScene::VideoScene(const std::string& path, std::uint32_t fourcc) : video_(open_video_file(path)), fourcc_(fourcc) {}

const std::vector<std::uint8_t>* VideoScene::frame(std::uint64_t) {
  cv::Mat bgr;
  if (!video_->read(bgr) || bgr.empty()) return nullptr;
  // A frame of another size is sent at its size, as a faulty sensor would: the recorder finds it does
  // not decode to the stream's size and counts it corrupt.
  if (fourcc_ == V4L2_PIX_FMT_YUYV) {
    payload_ = bgr_to_yuyv(bgr);
  } else {
    payload_.clear();
    media::encode_image(".jpg", bgr, payload_, {cv::IMWRITE_JPEG_QUALITY, kReplayJpegQuality});
  }
  return &payload_;
}

}  // namespace haptex::capture
