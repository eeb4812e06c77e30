#pragma once
// The frames of a press file (`haptex capture record`) as stored: MJPG bytes exactly as the sensor sent
// them ("jpeg"), or lossless PNG of raw YUYV frames ("png"), with the frame size and the rate the
// driver granted (schemas/hdf5-layout.md, "Press file"). Extraction reads presses back through it,
// and replay plays them.
#include <cstdint>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "core/h5/file.hpp"

namespace haptex::capture {

// The frame rates haptex takes from a file or a replay's fps= key: every tactile sensor's lies between.
inline constexpr double kLowestFps = 1, kHighestFps = 1000;

// A name ending in .h5 or .hdf5 (any case): how `capture extract` and replay tell press files from videos.
bool is_press_file_name(const std::string& path);

class PressFileFrames {
 public:
  // Throws haptex::Error (bad_input) naming the file and the object when it is not a press file.
  explicit PressFileFrames(std::string path);

  const std::string& path() const { return path_; }
  h5::Group root() const { return file_.root(); }  // for the attributes beyond the frames
  const std::string& encoding() const { return encoding_; }  // "jpeg" or "png"
  cv::Size size() const { return size_; }
  double fps() const { return fps_; }  // 0 when the file does not know it
  std::size_t count() const { return count_; }
  // Frame `index`'s bytes as stored. Throws haptex::Error (bad_input) naming the dataset when unreadable.
  std::vector<std::uint8_t> bytes(std::size_t index) const;

 private:
  std::string path_;
  h5::File file_;
  h5::Dataset frames_{h5::Handle(), "", ""};
  std::string encoding_;
  cv::Size size_;
  double fps_ = 0;
  std::size_t count_ = 0;
};

}  // namespace haptex::capture
