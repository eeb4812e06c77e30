#include "capture/device/fake_scene.hpp"
#include "media/codecs.hpp"

#include <linux/videodev2.h>

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace haptex::capture {
namespace {

cv::Mat gel_image(int width, int height) {
  // A lit gel: a soft gradient from one LED side to the other, with dark marker dots on a grid.
  cv::Mat gel(height, width, CV_32FC3);
  for (int y = 0; y < height; ++y) {
    auto* row = gel.ptr<cv::Vec3f>(y);
    for (int x = 0; x < width; ++x) {
      const float u = float(x) / float(width), v = float(y) / float(height);
      row[x] = cv::Vec3f(90 + 60 * u, 110 + 40 * v, 140 - 50 * u * v);
    }
  }
  const int spacing = std::max(8, width / 20), radius = std::max(1, spacing / 8);
  for (int y = spacing / 2; y < height; y += spacing)
    for (int x = spacing / 2; x < width; x += spacing) cv::circle(gel, {x, y}, radius, cv::Scalar(30, 30, 30), cv::FILLED);
  return gel;
}

cv::Mat indenter_shading(int width, int height) {
  // A round indenter in the middle: the gel brightens and tints where it is pushed in.
  cv::Mat blob(height, width, CV_32FC3);
  const double cx = width * 0.5, cy = height * 0.5, r = std::min(width, height) * 0.22;
  for (int y = 0; y < height; ++y) {
    auto* row = blob.ptr<cv::Vec3f>(y);
    for (int x = 0; x < width; ++x) {
      const double d2 = ((x - cx) * (x - cx) + (y - cy) * (y - cy)) / (r * r);
      const float w = float(std::exp(-d2 * 1.5));
      row[x] = cv::Vec3f(110 * w, 80 * w, -40 * w);
    }
  }
  return blob;
}

cv::Mat noise_pattern(int width, int height, std::uint64_t seed) {
  cv::Mat noise(height, width, CV_32FC3);
  cv::RNG rng(seed);
  rng.fill(noise, cv::RNG::NORMAL, 0.0, 1.5);
  return noise;
}

}  // namespace

// The float images every payload is made from. Outside the anonymous namespace: FakeScene::Images
// derives from it.
struct SceneImages {
  cv::Mat base, blob, noise[2];
  SceneImages(int width, int height, std::uint64_t seed)
      : base(gel_image(width, height)), blob(indenter_shading(width, height)),
        noise{noise_pattern(width, height, seed), noise_pattern(width, height, seed + 1)} {}
  cv::Mat render(int level, int noise_index) const {
    cv::Mat f = base + noise[noise_index & 1];
    if (level > 0) f += blob * (double(level) / FakeScene::kDepthLevels);
    cv::Mat out;
    f.convertTo(out, CV_8UC3);
    return out;
  }
};

std::vector<std::uint8_t> bgr_to_yuyv(const cv::Mat& bgr) {
  // ITU-R BT.601 in video range (Y 16..235, U and V 16..240), as UVC cameras send it and as OpenCV's
  // COLOR_YUV2BGR_YUYV (the recorder's decoder) reads it back; OpenCV's COLOR_BGR2YUV is full range,
  // and its frames would decode with their contrast stretched by 255/219.
  static const cv::Matx34f kBt601(24.966f / 255, 128.553f / 255, 65.481f / 255, 16,  // Y from B, G, R
                                  112.0f / 255, -74.203f / 255, -37.797f / 255, 128,  // U (Cb)
                                  -18.214f / 255, -93.786f / 255, 112.0f / 255, 128);  // V (Cr)
  cv::Mat yuv;
  cv::transform(bgr, yuv, kBt601);
  std::vector<std::uint8_t> out(std::size_t(bgr.rows) * bgr.cols * 2);
  std::size_t o = 0;
  for (int y = 0; y < yuv.rows; ++y) {
    const auto* row = yuv.ptr<cv::Vec3b>(y);
    for (int x = 0; x + 1 < yuv.cols; x += 2) {
      out[o++] = row[x][0];
      out[o++] = std::uint8_t((row[x][1] + row[x + 1][1] + 1) / 2);
      out[o++] = row[x + 1][0];
      out[o++] = std::uint8_t((row[x][2] + row[x + 1][2] + 1) / 2);
    }
  }
  return out;
}

struct FakeScene::Images : SceneImages {
  using SceneImages::SceneImages;
};

FakeScene::FakeScene(std::uint32_t fourcc, int width, int height, const PressSchedule& schedule, std::uint64_t seed)
    : fourcc_(fourcc), width_(width), height_(height), seed_(seed), schedule_(schedule), payloads_((kDepthLevels + 1) * 2 + 1) {}

FakeScene::~FakeScene() = default;

std::uint64_t FakeScene::press_period() const {
  return std::uint64_t(schedule_.rise_frames + schedule_.hold_frames + schedule_.release_frames + schedule_.gap_frames);
}

double FakeScene::depth(std::uint64_t frame) const {
  if (frame < first_press_frame()) return 0.0;
  const std::uint64_t since = frame - first_press_frame();
  if (schedule_.presses >= 0 && since / press_period() >= std::uint64_t(schedule_.presses)) return 0.0;
  const int t = int(since % press_period());
  const int rise = schedule_.rise_frames, hold = schedule_.hold_frames, release = schedule_.release_frames;
  if (t < rise) return double(t + 1) / rise;
  if (t < rise + hold) return 1.0;
  if (t < rise + hold + release) return 1.0 - double(t - rise - hold + 1) / (release + 1);
  return 0.0;
}

cv::Mat FakeScene::image(int level, int noise) const { return render_gel(width_, height_, level, noise, seed_); }

cv::Mat render_gel(int width, int height, int level, int noise_pattern, std::uint64_t seed) {
  return SceneImages(width, height, seed).render(level, noise_pattern);
}

std::vector<std::uint8_t> FakeScene::encode(const cv::Mat& bgr) const {
  if (fourcc_ == V4L2_PIX_FMT_YUYV) return bgr_to_yuyv(bgr);
  std::vector<std::uint8_t> jpeg;
  media::encode_image(".jpg", bgr, jpeg, {cv::IMWRITE_JPEG_QUALITY, 90});
  return jpeg;
}

const std::vector<std::uint8_t>& FakeScene::payload(std::uint64_t frame) const {
  const std::size_t black_index = payloads_.size() - 1;
  const int level = black(frame) ? 0 : int(std::lround(depth(frame) * kDepthLevels));
  const std::size_t index = black(frame) ? black_index : std::size_t(level * 2 + int(frame & 1));
  std::vector<std::uint8_t>& bytes = payloads_[index];
  if (!bytes.empty()) return bytes;
  if (index == black_index) {
    bytes = encode(cv::Mat::zeros(height_, width_, CV_8UC3));
  } else {
    if (!images_) images_ = std::make_unique<Images>(width_, height_, seed_);
    bytes = encode(images_->render(level, int(frame & 1)));
  }
  if (++rendered_ == payloads_.size()) images_.reset();
  return bytes;
}

}  // namespace haptex::capture
