#include "capture/replay/press_file_scene.hpp"

#include <linux/videodev2.h>


#include "capture/device/fake_scene.hpp"
#include "capture/replay/video_scene.hpp"
#include "capture/scoring/scoring_image.hpp"
#include "core/error.hpp"
#include "core/image_header.hpp"
#include "dataset/decode_image.hpp"
#include "dataset/layout.hpp"
#include "media/codecs.hpp"

namespace haptex::capture {

FakeMode press_file_replay_mode(const std::string& path) {
  const dataset::PressFile frames(path);
  // Review 5: frames whose JPEGs state 60000x60000 replayed as "MJPG 320x240" and gave no press, exit
  // 0; extraction refuses a file of which no frame decodes, and so does replay (a frame the recorder
  // stored cut off is empty, and others may be).
  const auto of_the_file = [&](std::size_t i) {
    const std::optional<ImageSize> s = image_header_size(frames.bytes(i));
    return s && int(s->width) == frames.size().width && int(s->height) == frames.size().height;
  };
  bool any = false;
  for (std::size_t i = 0; i < frames.count() && !any; ++i) any = of_the_file(i);
  if (frames.count() > 0 && !any)
    throw input_error(path, "/frames", "holds no image of the press file's " + std::to_string(frames.size().width) + "x" +
                                           std::to_string(frames.size().height) + " frames (damaged, or of another size)",
                      "Copy the file again from the machine that recorded it");
  FakeMode mode;
  mode.fourcc = frames.encoding() == "jpeg" ? V4L2_PIX_FMT_MJPEG : V4L2_PIX_FMT_YUYV;
  mode.width = std::uint32_t(frames.size().width);
  mode.height = std::uint32_t(frames.size().height);
  mode.fps = {frames.fps()};
  return mode;
}

PressFileScene::PressFileScene(const std::string& path)
    : frames_(path), order_(dataset::read_channel_order(frames_.root(), dataset::layout::kReference)) {}

const std::vector<std::uint8_t>* PressFileScene::frame(std::uint64_t k) {
  if (k >= frames_.count()) return nullptr;
  payload_ = frames_.bytes(std::size_t(k));
  const bool jpeg = frames_.encoding() == "jpeg";
  if (jpeg && (order_ == dataset::kWrittenChannelOrder || !is_complete_jpeg(payload_))) return &payload_;
  const cv::Mat bgr = dataset::decode_image(payload_);
  if (bgr.size() != frames_.size()) {
    // The recorder stored a cut-off raw frame empty: send a third of a frame, as the fake camera's corrupt fault does.
    payload_.assign(std::size_t(frames_.size().area()) * 2 / 3, 0);
    return &payload_;
  }
  // Frames stored B, G, R decode to R, G, B where OpenCV expects B, G, R: the sensor sent them swapped back.
  if (order_ == dataset::ChannelOrder::bgr)
    dataset::reorder_channels({bgr.data, bgr.total() * 3}, dataset::ChannelOrder::rgb, dataset::ChannelOrder::bgr);
  if (jpeg)
    media::encode_image(".jpg", bgr, payload_, {cv::IMWRITE_JPEG_QUALITY, kReplayJpegQuality});
  else
    payload_ = bgr_to_yuyv(bgr);
  return &payload_;
}

}  // namespace haptex::capture
