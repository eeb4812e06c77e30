#include "capture/storage/press_file_frames.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "dataset/vlen_bytes.hpp"
#include "core/error.hpp"
#include "core/text/format.hpp"
#include "dataset/format.hpp"
#include "dataset/layout.hpp"

namespace haptex::capture {

bool is_press_file_name(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext == ".h5" || ext == ".hdf5";
}

PressFileFrames::PressFileFrames(std::string path)
    : path_(std::move(path)), file_(dataset::open_checked(path_, dataset::Kind::press)) {
  const h5::Group root = file_.root();
  frames_ = root.open_dataset(dataset::layout::kFrames);
  if (!dataset::is_vlen_bytes(frames_))
    throw input_error(path_, "/frames", "expected variable-length uint8 frames", "Record the press again");
  encoding_ = root.attr_string(dataset::layout::kEncoding);
  if (encoding_ != "jpeg" && encoding_ != "png")
    throw input_error(path_, "/", "unknown frame encoding '" + encoding_ + "'", "Expected jpeg or png");
  const std::int64_t width = root.attr_int(dataset::layout::kWidth), height = root.attr_int(dataset::layout::kHeight);
  // 65535: V4L2 frame sizes; anything else is a damaged attribute, not a frame size.
  if (width <= 0 || height <= 0 || width > 65535 || height > 65535)
    throw input_error(path_, "/@width, /@height", std::to_string(width) + " x " + std::to_string(height) + " is not a frame size",
                      "Record the press again");
  size_ = cv::Size(int(width), int(height));
  fps_ = root.attr_double(dataset::layout::kFps);
  if (fps_ != 0 && !(fps_ >= kLowestFps && fps_ <= kHighestFps))  // 0: not known (replay then needs fps=)
    throw input_error(path_, "/@fps", text::format("is %g, neither 0 (not known) nor a frame rate of %g to %g frames per second",
                                                   fps_, kLowestFps, kHighestFps),
                      "Record the press again, or replay it with replay:FILE,fps=N");
  count_ = frames_.shape().at(0);
}

std::vector<std::uint8_t> PressFileFrames::bytes(std::size_t index) const { return dataset::read_vlen_bytes(frames_, index); }

}  // namespace haptex::capture
