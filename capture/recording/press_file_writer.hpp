#pragma once
// The capture half of writing a press file (the file itself: dataset/press_file.hpp): frames stored as
// the sensor sent them (MJPG bytes untouched; raw YUYV as lossless PNG), lost frames counted from the
// driver's sequence numbers and timestamps, and what the take processor needs of the press afterwards.
#include <cstdint>
#include <string>

#include <opencv2/core.hpp>

#include "capture/device/drop_counter.hpp"
#include "capture/device/frame.hpp"
#include "dataset/press_file.hpp"

namespace haptex::capture {

struct PressFileSummary {
  std::string path;
  std::uint64_t frames = 0, dropped_frames = 0, error_frames = 0, corrupt_frames = 0;
  std::int64_t contact_first = -1, contact_last = -1, peak = -1;  // indices into the file's frames
  std::uint32_t first_sequence = 0, last_sequence = 0;
  std::string ended_by;
};

// The header of a press file from the sensor's format: its fourcc as text, how its frames are stored.
dataset::PressFileHeader press_file_header(std::uint32_t fourcc, int width, int height);

class PressFileWriter {
 public:
  // `header` as press_file_header made it, the rest filled in; `reference` is the no-contact reference
  // image (BGR, the frame size).
  PressFileWriter(const std::string& path, const dataset::PressFileHeader& header, const cv::Mat& reference);
  // error_buffers: buffers flagged by the driver since the previous appended frame.
  void append(const Frame& frame, float score, std::uint64_t error_buffers);
  void mark_contact(std::int64_t first, std::int64_t last, std::int64_t peak);  // indices into this file's frames
  std::size_t frames() const { return file_.frames(); }
  // Writes the per-frame arrays and attributes and renames the file into place.
  PressFileSummary finish(const std::string& ended_by);

 private:
  std::vector<std::uint8_t> stored(const Frame& frame) const;
  bool jpeg_;
  cv::Size size_;
  dataset::PressFileWriter file_;
  DropCounter drops_;
  PressFileSummary summary_;
};

}  // namespace haptex::capture
