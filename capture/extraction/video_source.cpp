// Video files through OpenCV's FFmpeg backend (MJPG/MPEG-4 AVI, FFV1 Matroska, H.264 MP4 ...).
#include <vector>

#include "capture/extraction/frame_source.hpp"
#include "capture/scoring/scoring_image.hpp"
#include "capture/storage/video_file.hpp"
#include "core/error.hpp"
#include "core/image_header.hpp"
#include "core/sha256.hpp"
#include "dataset/decode_image.hpp"
#include "media/codecs.hpp"

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
    const std::unique_ptr<media::VideoReader> video = open(path_);
    cache_.clear();
    cached_ = true;
    cached_bytes_ = 0;
    std::int64_t read = 0;
    for (Frame f; next(*video, f, read); ++read) {
      visit(read, f.bgr.empty() ? cv::Mat() : scoring_image(f.bgr), f.bgr);
      keep(std::move(f));
    }
    // The container's count is exact for AVI and MP4 indices and an estimate (duration x fps) for
    // Matroska: one frame of slack, so only a real shortfall counts.
    const auto announced = std::int64_t(video->get(cv::CAP_PROP_FRAME_COUNT));
    frames_missing_ = announced > read + 1 ? announced - read : 0;
  }

  std::int64_t frames_missing() const override { return frames_missing_; }

  void read(const std::vector<std::int64_t>& indices, const Delivery& deliver) override {
    if (cached_) {
      for (std::int64_t i : indices) deliver_frame(cache_.at(std::size_t(i)), i, deliver);
      return;
    }
    const std::unique_ptr<media::VideoReader> video = open(path_);
    std::size_t next_wanted = 0;
    // Seeking is unreliable in inter-coded videos; reading on, and converting only the frames we
    // keep (grab without retrieve), is exact.
    for (std::int64_t i = 0; next_wanted < indices.size(); ++i) {
      if (!video->grab())
        throw input_error(path_, "frame " + std::to_string(indices[next_wanted]),
                          "the video ended before this frame on the second reading", "The file may be damaged; re-export it");
      if (i != indices[next_wanted]) continue;
      Frame f;
      retrieve(*video, f, i);
      deliver_frame(f, i, deliver);
      ++next_wanted;
    }
  }

 private:
  // A frame as read: decoded (empty when it does not decode) and, from an MJPG video, its JPEG.
  struct Frame {
    cv::Mat bgr;
    dataset::EncodedImage jpeg;
  };

  // An MJPG video is read raw, each frame's JPEG as the file holds it: kept as it is, it costs a
  // tenth of the decoded frame, and it is decoded here exactly as it will be read back.
  std::unique_ptr<media::VideoReader> open(const std::string& path) const {
    std::unique_ptr<media::VideoReader> video = open_video_file(path);
    if (probe_.mjpeg && !video->set(cv::CAP_PROP_FORMAT, -1))
      throw failure(path + ": OpenCV's FFmpeg backend cannot read this MJPG video's frames raw");
    return video;
  }

  bool next(media::VideoReader& video, Frame& f, std::int64_t index) const {
    if (!probe_.mjpeg) {  // a frame that does not decode ends the reading (frames_missing counts the rest)
      if (!video.read(f.bgr)) return false;
      check_size(f.bgr, index);
      return true;
    }
    if (!video.grab()) return false;
    retrieve(video, f, index);
    return true;
  }

  void retrieve(media::VideoReader& video, Frame& f, std::int64_t index) const {
    cv::Mat raw;
    video.retrieve(raw);
    if (!probe_.mjpeg) {
      f.bgr = raw;
      check_size(f.bgr, index);
      return;
    }
    f.jpeg.assign(raw.data, raw.data + raw.total() * raw.elemSize());
    f.bgr = decode(f.jpeg);
  }

  // A frame's JPEG, decoded when whole and of the video's size by its header (so a damaged packet
  // neither decodes concealed nor makes OpenCV allocate more); empty otherwise.
  cv::Mat decode(const dataset::EncodedImage& jpeg) const {
    const std::optional<ImageSize> size = image_header_size(jpeg);
    if (!size || cv::Size(int(size->width), int(size->height)) != probe_.size) return {};
    return dataset::decode_jpeg(jpeg);  // empty when cut off
  }

  void deliver_frame(const Frame& f, std::int64_t index, const Delivery& deliver) const {
    const cv::Mat bgr = f.bgr.empty() && !f.jpeg.empty() ? decode(f.jpeg) : f.bgr;
    if (bgr.empty())
      throw input_error(path_, "frame " + std::to_string(index), "the frame does not decode", "The file may be damaged; re-export it");
    deliver(index, bgr, f.jpeg);
  }

  // Decoding lossless video (FFV1) costs more than anything else extraction does, so a video whose
  // frames fit in kCacheBytes (decoded, or an MJPG video's JPEGs) is read once and its frames kept;
  // a longer one is read a second time. (A frame read owns its pixels: read() copies them out of the
  // decoder, so keeping it needs no copy.)
  void keep(Frame&& f) {
    if (!cached_) return;
    cached_bytes_ += probe_.mjpeg ? f.jpeg.size() : f.bgr.total() * f.bgr.elemSize();
    if (cached_bytes_ > kCacheBytes) {
      cache_.clear();
      cached_ = false;
      return;
    }
    if (probe_.mjpeg) f.bgr.release();  // decoded again when kept: a tenth of the memory
    cache_.push_back(std::move(f));
  }

  void check_size(const cv::Mat& frame, std::int64_t index) const {
    if (frame.size() != probe_.size || frame.type() != CV_8UC3)
      throw input_error(path_, "frame " + std::to_string(index),
                        "frame size or type changes within the video", "Re-export the video with one frame size");
  }

  static constexpr std::size_t kCacheBytes = std::size_t(128) << 20;
  std::string path_;
  VideoProbe probe_;
  std::vector<Frame> cache_;
  bool cached_ = false;
  std::size_t cached_bytes_ = 0;
  std::int64_t frames_missing_ = 0;
};

}  // namespace

std::unique_ptr<FrameSource> open_video(const std::string& path) { return std::make_unique<VideoSource>(path); }

}  // namespace haptex::capture
