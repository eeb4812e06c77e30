// Video files through OpenCV's FFmpeg backend (MJPG/MPEG-4 AVI, FFV1 Matroska, H.264 MP4 ...).
#include <vector>

#include "capture/extraction/frame_source.hpp"
#include "capture/scoring/scoring_image.hpp"
#include "capture/storage/video_file.hpp"
#include "core/error.hpp"
#include "core/sha256.hpp"

namespace haptex::capture {
namespace {

class VideoSource : public FrameSource {
 public:
  explicit VideoSource(std::string path) : path_(std::move(path)), probe_(probe_video_file(path_)) {}

  const std::string& path() const override { return path_; }
  std::string sha256() const override { return sha256_file(path_); }
  bool lossless() const override { return probe_.lossless; }
  bool inter_frame() const override { return probe_.inter_frame; }
  cv::Size frame_size() const override { return probe_.size; }
  double fps() const override { return probe_.fps; }

  void scan(const Visitor& visit, const std::function<bool(std::int64_t)>&) override {
    cv::VideoCapture video = open_video_file(path_);
    cv::Mat frame;
    cache_.clear();
    cached_ = true;
    std::int64_t decoded = 0;
    for (; video.read(frame); ++decoded) {
      check_size(frame, decoded);
      visit(decoded, scoring_image(frame), frame);
      keep(frame);
    }
    // The container's count is exact for AVI and MP4 indices and an estimate (duration x fps) for
    // Matroska: one frame of slack, so only a real shortfall counts.
    const auto announced = std::int64_t(video.get(cv::CAP_PROP_FRAME_COUNT));
    frames_missing_ = announced > decoded + 1 ? announced - decoded : 0;
  }

  std::int64_t frames_missing() const override { return frames_missing_; }

  void read(const std::vector<std::int64_t>& indices,
            const std::function<void(std::int64_t, const cv::Mat&)>& deliver) override {
    if (cached_) {
      for (std::int64_t i : indices) deliver(i, cache_.at(std::size_t(i)));
      return;
    }
    cv::VideoCapture video = open_video_file(path_);
    std::size_t next = 0;
    cv::Mat frame;
    // Seeking is unreliable in inter-coded videos; reading on, and converting only the frames we
    // keep (grab without retrieve), is exact.
    for (std::int64_t i = 0; next < indices.size(); ++i) {
      if (!video.grab())
        throw input_error(path_, "frame " + std::to_string(indices[next]),
                          "the video ended before this frame on the second reading", "The file may be damaged; re-export it");
      if (i != indices[next]) continue;
      video.retrieve(frame);
      check_size(frame, i);
      deliver(i, frame);
      ++next;
    }
  }

 private:
  // Decoding lossless video (FFV1) costs more than anything else extraction does, so a video that
  // fits in kCacheBytes is decoded once and its frames kept; a longer one is read a second time.
  void keep(const cv::Mat& frame) {
    if (!cached_) return;
    if ((cache_.size() + 1) * frame.total() * frame.elemSize() > kCacheBytes) {
      cache_.clear();
      cached_ = false;
      return;
    }
    cache_.push_back(frame.clone());
  }

  void check_size(const cv::Mat& frame, std::int64_t index) const {
    if (frame.size() != probe_.size || frame.type() != CV_8UC3)
      throw input_error(path_, "frame " + std::to_string(index),
                        "frame size or type changes within the video", "Re-export the video with one frame size");
  }

  static constexpr std::size_t kCacheBytes = std::size_t(512) << 20;
  std::string path_;
  VideoProbe probe_;
  std::vector<cv::Mat> cache_;
  bool cached_ = false;
  std::int64_t frames_missing_ = 0;
};

}  // namespace

std::unique_ptr<FrameSource> open_video(const std::string& path) { return std::make_unique<VideoSource>(path); }

}  // namespace haptex::capture
