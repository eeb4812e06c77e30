#pragma once
// Where `capture extract` reads frames from: a video file (anything OpenCV's FFmpeg backend reads), a
// folder of frame images (a PNG sequence), or a press file. Extraction reads a source twice: once for every frame's small scoring image, then
// once more for the few full frames it keeps, so memory stays small however long the video is.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "capture/scoring/contact_score.hpp"
#include "dataset/press_images.hpp"

namespace haptex::capture {

class FrameSource {
 public:
  virtual ~FrameSource() = default;
  virtual const std::string& path() const = 0;
  virtual cv::Size frame_size() const = 0;
  virtual double fps() const = 0;  // 0 when the source does not say
  // True when frames reach us exactly as the sensor (or renderer) made them: no compression artefacts.
  virtual bool lossless() const = 0;
  // True when frames are coded from earlier frames (MPEG-4, H.264, ...): frames between key frames
  // copy each other's compression noise, so the noise of the first few frames says little about the
  // rest (the thresholds then take a longer calibration; contact_score.hpp). Image folders, press
  // files, MJPG and lossless codecs code every frame on its own.
  virtual bool inter_frame() const { return false; }
  // SHA-256 of the source's bytes (for a folder of images: of the images' bytes in frame order).
  virtual std::string sha256() const = 0;

  // Calls visit(index, scoring image, full frame) for every frame in order. The scoring image is
  // empty for a frame that does not decode. `full` is the decoded BGR frame when decoding it was
  // needed anyway (videos), else empty; with need_full (the first frames, for a reference) it is
  // always decoded.
  using Visitor = std::function<void(std::int64_t index, const cv::Mat& scoring, const cv::Mat& full)>;
  virtual void scan(const Visitor& visit, const std::function<bool(std::int64_t)>& need_full) = 0;
  // Full BGR frames at the given indices (ascending), delivered in order, each with the source's own
  // JPEG or PNG bytes of it when it has them in true colours (MJPG videos, image files, press files
  // stored RGB), which the gelsight file then stores as they are; else the bytes are empty.
  using Delivery = std::function<void(std::int64_t index, const cv::Mat& bgr, const dataset::EncodedImage& encoded)>;
  virtual void read(const std::vector<std::int64_t>& indices, const Delivery& deliver) = 0;

  // A source that carries its own no-contact reference and thresholds (press files).
  struct StoredReference {
    cv::Mat image;  // BGR
    float noise = 0, pixel_threshold = 0, trigger = 0, level = 0;  // level 0: a file from before it was stored
  };
  virtual std::optional<StoredReference> stored_reference() const { return std::nullopt; }
  // The material a source names itself (press files); empty for videos.
  virtual std::string material() const { return {}; }
  // After scan: frames the source announced but that never decoded (a video cut short or damaged).
  virtual std::int64_t frames_missing() const { return 0; }
};

// Throws haptex::Error (bad_input) naming the file when OpenCV cannot open it or it has no frames.
std::unique_ptr<FrameSource> open_video(const std::string& path);
// The images of a folder, in name order (numbers compared by value), as the frames of a video.
// Throws haptex::Error (bad_input) naming the folder or image when one does not read or sizes differ.
std::unique_ptr<FrameSource> open_image_sequence(const std::string& folder);
// Throws haptex::Error (bad_input) naming the file and object when it is not a press file.
std::unique_ptr<FrameSource> open_press_file(const std::string& path);

}  // namespace haptex::capture
