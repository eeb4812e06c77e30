// Video files through OpenCV's FFmpeg backend (MJPG/MPEG-4 AVI, FFV1 Matroska, H.264 MP4 ...).
#include <cstdlib>
#include <vector>
#include <opencv2/videoio.hpp>

#include "capture/extraction/frame_source.hpp"
#include "capture/scoring/scoring_image.hpp"
#include "core/error.hpp"
#include "core/sha256.hpp"

namespace haptex::capture {
namespace {

class VideoSource : public FrameSource {
 public:
  explicit VideoSource(std::string path) : path_(std::move(path)) {
    cv::VideoCapture video = open();
    cv::Mat first;
    if (!video.read(first) || first.empty())
      throw input_error(path_, "frame 0", "the video has no readable frame",
                        "Check it plays (ffprobe " + path_ + "); re-export it as FFV1 .mkv or MJPG .avi");
    size_ = first.size();
    fps_ = video.get(cv::CAP_PROP_FPS);
    fourcc_ = std::uint32_t(video.get(cv::CAP_PROP_FOURCC));
  }

  const std::string& path() const override { return path_; }
  std::string sha256() const override { return sha256_file(path_); }
  bool lossless() const override {
    // FFV1, HuffYUV, PNG-in-AVI and uncompressed video.
    for (const char* codec : {"FFV1", "FFVH", "HFYU", "png ", "MPNG", "UYVY", "YUY2", "I420", "Y800", "RGBA", "BGRA"})
      if (fourcc_ == std::uint32_t(cv::VideoWriter::fourcc(codec[0], codec[1], codec[2], codec[3]))) return true;
    return fourcc_ == 0;
  }
  bool inter_frame() const override {
    for (const char* codec : {"MJPG", "mjpg", "AVRn", "dmb1", "jpeg"})
      if (fourcc_ == std::uint32_t(cv::VideoWriter::fourcc(codec[0], codec[1], codec[2], codec[3]))) return false;
    return !lossless();
  }
  cv::Size frame_size() const override { return size_; }
  double fps() const override { return fps_ > 0 && fps_ < 1000 ? fps_ : 0.0; }

  void scan(const Visitor& visit, const std::function<bool(std::int64_t)>&) override {
    cv::VideoCapture video = open();
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
    cv::VideoCapture video = open();
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
  cv::VideoCapture open() const {
    // FFmpeg logs decoding problems of damaged videos straight to stderr; libraries here never print
    // (damage shows as frames that do not decode). OpenCV reads this once, when FFmpeg is first used;
    // a user's own setting wins.
    setenv("OPENCV_FFMPEG_LOGLEVEL", "-8", 0);  // AV_LOG_QUIET
    // A packet cut short (a truncated file) would decode, concealed, into a frame whose missing part
    // differs from the reference and so scores as the strongest contact: FFmpeg's demuxer drops such
    // packets instead (read per open, so it applies to this video).
    setenv("OPENCV_FFMPEG_CAPTURE_OPTIONS", "fflags;discardcorrupt", 0);
    cv::VideoCapture video;
    // FFmpeg only: other backends (GStreamer) print their own warnings on failure, and libraries
    // here never print.
    try {
      video.open(path_, cv::CAP_FFMPEG);
    } catch (const cv::Exception&) {
    }
    if (!video.isOpened())
      throw input_error(path_, "", "OpenCV cannot open this as a video",
                        "Give a video file (.avi, .mkv, .mp4 ...) or a press file (.h5) from 'haptex capture record'");
    return video;
  }

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
    if (frame.size() != size_ || frame.type() != CV_8UC3)
      throw input_error(path_, "frame " + std::to_string(index),
                        "frame size or type changes within the video", "Re-export the video with one frame size");
  }

  static constexpr std::size_t kCacheBytes = std::size_t(512) << 20;
  std::string path_;
  cv::Size size_;
  double fps_ = 0;
  std::uint32_t fourcc_ = 0;
  std::vector<cv::Mat> cache_;
  bool cached_ = false;
  std::int64_t frames_missing_ = 0;
};

}  // namespace

std::unique_ptr<FrameSource> open_video(const std::string& path) { return std::make_unique<VideoSource>(path); }

}  // namespace haptex::capture
