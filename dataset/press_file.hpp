#pragma once
// The press file (schemas/hdf5-layout.md, "Press file"), reader and writer side by side: one press as
// `haptex capture record` took it. The frames as the sensor sent them (MJPG bytes untouched, "jpeg";
// raw formats as lossless PNG, "png"), their timestamps, sequence numbers, flags and live contact
// scores, the session's no-contact reference (uint8 H x W x 3, RGB, its order stated), and the device,
// format, controls, material, thresholds and loss counts as attributes. Extraction reads presses
// back through PressFile, and replay plays them.
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "core/h5/atomic_file.hpp"
#include "core/h5/file.hpp"
#include "dataset/vlen_bytes.hpp"

namespace haptex::dataset {

// The frame rates haptex takes from a file or a replay's fps= key: every tactile sensor's lies between.
inline constexpr double kLowestFps = 1, kHighestFps = 1000;

// A name ending in .h5 or .hdf5 (any case): how `capture extract` and replay tell press files from videos.
bool is_press_file_name(const std::string& path);

// What a press file states of its sensor, take and thresholds, known when its first frame comes.
struct PressFileHeader {
  std::string material;
  int press_index = 0;
  std::string device, card, driver, bus_info, serial;
  std::string fourcc;    // the sensor's format as text ("MJPG", "YUYV")
  std::string encoding;  // how the frames are stored: "jpeg" or "png"
  std::string frames_description;
  int width = 0, height = 0;
  double fps = 0, requested_fps = 0;
  std::string locked_controls = "[]", missing_controls = "[]";  // JSON arrays, as in the session manifest
  float noise = 0, pixel_threshold = 0, trigger = 0, level = 0;
  std::string provenance;
};

// What only the end of the press knows.
struct PressFileTrailer {
  std::uint64_t dropped_frames = 0, error_frames = 0, corrupt_frames = 0;
  std::int64_t contact_first = -1, contact_last = -1, peak = -1;  // indices into the file's frames
  std::string ended_by;
};

class PressFileWriter {
 public:
  // `reference` is the no-contact reference image (BGR, the frame size). The file appears under its
  // final name only at finish() (h5::AtomicFile).
  PressFileWriter(const std::string& path, const PressFileHeader& header, const cv::Mat& reference);
  // One frame as stored (empty: it arrived cut off), with what the driver said of it.
  void append(std::span<const std::uint8_t> stored, std::int64_t timestamp_ns, std::uint32_t sequence, std::uint32_t flags,
              float score);
  std::size_t frames() const { return timestamps_.size(); }
  // Writes the per-frame arrays and the attributes and renames the file into place.
  void finish(const PressFileTrailer& trailer);

 private:
  PressFileHeader header_;
  std::unique_ptr<h5::AtomicFile> file_;
  std::unique_ptr<VlenBytesWriter> frames_;
  std::vector<std::int64_t> timestamps_;
  std::vector<std::uint32_t> sequences_, flags_;
  std::vector<float> scores_;
};

class PressFile {
 public:
  // Throws haptex::Error (bad_input) naming the file and the object when it is not a press file.
  explicit PressFile(std::string path);

  const std::string& path() const { return path_; }
  h5::Group root() const { return file_.root(); }  // for the attributes beyond the frames
  const std::string& encoding() const { return encoding_; }  // "jpeg" or "png"
  cv::Size size() const { return size_; }
  double fps() const { return fps_; }  // 0 when the file does not know it
  std::size_t count() const { return count_; }
  // Frame `index`'s bytes as stored. Throws haptex::Error (bad_input) naming the dataset when unreadable.
  std::vector<std::uint8_t> bytes(std::size_t index) const;
  // The no-contact reference as BGR, whatever order it states. Throws haptex::Error (bad_input) naming
  // the object when it is no H x W x 3 uint8 image of the frame size or its order is unknown.
  cv::Mat reference() const;

 private:
  // A damaged file (exit 2): names the object, says to record the press again.
  [[noreturn]] void refuse(const std::string& where, const std::string& what) const;
  void require_consistent_frames(const h5::Group& root) const;
  void require_frame_order(const h5::Group& root) const;
  void require_control_lists(const h5::Group& root) const;
  void require_reference_shape(const h5::Group& root) const;
  std::string path_;
  h5::File file_;
  h5::Dataset frames_{h5::Handle(), "", ""};
  std::string encoding_;
  cv::Size size_;
  double fps_ = 0;
  std::size_t count_ = 0;
};

}  // namespace haptex::dataset
