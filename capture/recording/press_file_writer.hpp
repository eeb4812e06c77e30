#pragma once
// One press file (schemas/hdf5-layout.md "Press file"): the frames of one press as the sensor sent
// them (MJPG bytes untouched; raw formats as lossless PNG), their timestamps, sequence numbers, flags
// and live contact scores, the session's no-contact reference, and the device, format, controls,
// material and loss counts as attributes. Frames are appended as they come; the file appears under its
// final name only at finish().
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "capture/device/drop_counter.hpp"
#include "capture/device/frame.hpp"
#include "dataset/vlen_bytes.hpp"
#include "core/h5/atomic_file.hpp"

namespace haptex::capture {

struct PressFileInfo {
  std::string material;
  int press_index = 0;
  std::string device, card, driver, bus_info, serial;
  std::uint32_t fourcc = 0;
  int width = 0, height = 0;
  double fps = 0, requested_fps = 0;
  std::string locked_controls = "[]", missing_controls = "[]";  // JSON arrays, as in the session manifest
  float noise = 0, pixel_threshold = 0, trigger = 0, level = 0;
  std::string provenance;
};

struct PressFileSummary {
  std::string path;
  std::uint64_t frames = 0, dropped_frames = 0, error_frames = 0, corrupt_frames = 0;
  std::int64_t contact_first = -1, contact_last = -1, peak = -1;  // indices into the file's frames
  std::uint32_t first_sequence = 0, last_sequence = 0;
  std::string ended_by;
};

class PressFileWriter {
 public:
  // `reference` is the no-contact reference image (BGR, the frame size).
  PressFileWriter(const std::string& path, const PressFileInfo& info, const cv::Mat& reference);
  // error_buffers: buffers flagged by the driver since the previous appended frame.
  void append(const Frame& frame, float score, std::uint64_t error_buffers);
  void mark_contact(std::int64_t first, std::int64_t last, std::int64_t peak);  // indices into this file's frames
  std::size_t frames() const { return timestamps_.size(); }
  // Writes the per-frame arrays and attributes and renames the file into place.
  PressFileSummary finish(const std::string& ended_by);

 private:
  std::vector<std::uint8_t> encode(const Frame& frame) const;
  PressFileInfo info_;
  std::unique_ptr<h5::AtomicFile> file_;
  std::unique_ptr<dataset::VlenBytesWriter> frames_;
  std::vector<std::int64_t> timestamps_;
  std::vector<std::uint32_t> sequences_, flags_;
  std::vector<float> scores_;
  DropCounter drops_;
  PressFileSummary summary_;
};

}  // namespace haptex::capture
