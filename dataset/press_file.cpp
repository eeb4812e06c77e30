#include "dataset/press_file.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>

#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"
#include "core/image_header.hpp"
#include "core/naming.hpp"
#include "core/text/format.hpp"
#include "dataset/channel_order.hpp"
#include "dataset/description.hpp"
#include "dataset/format.hpp"
#include "dataset/layout.hpp"

namespace haptex::dataset {
namespace {

// The reference: uint8 H x W x 3 in RGB order (what h5py, PIL and matplotlib users expect; its
// channel_order attribute says so), one image per chunk, gzip level 1 (images barely compress
// further, and a 3280 x 2464 frame at level 4 would take longer than a frame period).
void write_reference(h5::Group& root, const cv::Mat& bgr) {
  CV_Assert(bgr.type() == CV_8UC3);
  cv::Mat rgb;
  cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
  if (!rgb.isContinuous()) rgb = rgb.clone();
  h5::DatasetOptions options;
  options.gzip_level = 1;
  options.chunk = {hsize_t(bgr.rows), hsize_t(bgr.cols), 3};
  h5::Dataset d = root.write_array<std::uint8_t>(layout::kReference, std::span<const std::uint8_t>(rgb.data, rgb.total() * 3),
                                                 {hsize_t(bgr.rows), hsize_t(bgr.cols), 3}, options);
  describe(d, "", "no-contact reference: mean of the frames taken before the presses");
  d.set_attr(layout::kChannelOrder, channel_order_name(kWrittenChannelOrder));
}

void write_header(h5::Group& root, const PressFileHeader& h) {
  stamp(root, Kind::press, h.provenance);
  root.set_attr(layout::kPressMaterial, h.material);
  root.set_attr(layout::kPressMaterialId, material_id(h.material));
  root.set_attr(layout::kPressIndex, h.press_index);
  root.set_attr(layout::kDevice, h.device);
  root.set_attr(layout::kCard, h.card);
  root.set_attr(layout::kDriver, h.driver);
  root.set_attr(layout::kBusInfo, h.bus_info);
  root.set_attr(layout::kSerial, h.serial);
  root.set_attr(layout::kFourcc, h.fourcc);
  root.set_attr(layout::kEncoding, h.encoding);
  // JPEG and PNG decode to R, G, B, and the reference is written RGB.
  root.set_attr(layout::kChannelOrder, channel_order_name(kWrittenChannelOrder));
  root.set_attr(layout::kWidth, h.width);
  root.set_attr(layout::kHeight, h.height);
  root.set_attr(layout::kFps, h.fps);
  root.set_attr(layout::kRequestedFps, h.requested_fps);
  root.set_attr(layout::kLockedControls, h.locked_controls);
  root.set_attr(layout::kMissingControls, h.missing_controls);
  root.set_attr(layout::kNoise, double(h.noise));
  root.set_attr(layout::kPixelThreshold, double(h.pixel_threshold));
  root.set_attr(layout::kTrigger, double(h.trigger));
  root.set_attr(layout::kNoContactLevel, double(h.level));
}

void write_trailer(h5::Group& root, const PressFileTrailer& t, std::size_t frames) {
  root.set_attr(layout::kSamples, std::int64_t(frames));
  root.set_attr(layout::kDroppedFrames, std::int64_t(t.dropped_frames));
  root.set_attr(layout::kErrorFrames, std::int64_t(t.error_frames));
  root.set_attr(layout::kCorruptFrames, std::int64_t(t.corrupt_frames));
  root.set_attr(layout::kContactFirst, t.contact_first);
  root.set_attr(layout::kContactLast, t.contact_last);
  root.set_attr(layout::kPeakFrame, t.peak);
  root.set_attr(layout::kEndedBy, t.ended_by);
}

}  // namespace

bool is_press_file_name(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext == ".h5" || ext == ".hdf5";
}

PressFileWriter::PressFileWriter(const std::string& path, const PressFileHeader& header, const cv::Mat& reference)
    : header_(header), file_(std::make_unique<h5::AtomicFile>(path, false)) {
  h5::Group root = file_->root();
  frames_ = std::make_unique<VlenBytesWriter>(root, layout::kFrames);
  describe(frames_->dataset(), "", header.frames_description);
  write_reference(root, reference);
}

void PressFileWriter::append(std::span<const std::uint8_t> stored, std::int64_t timestamp_ns, std::uint32_t sequence,
                             std::uint32_t flags, float score) {
  frames_->append(stored);
  timestamps_.push_back(timestamp_ns);
  sequences_.push_back(sequence);
  flags_.push_back(flags);
  scores_.push_back(score);
}

void PressFileWriter::finish(const PressFileTrailer& trailer) {
  h5::Group root = file_->root();
  describe(root.write(layout::kTimestampNs, timestamps_), "ns", "CLOCK_MONOTONIC time the driver stamped on each frame");
  describe(root.write(layout::kSequence, sequences_), "", "the driver's frame counter; a gap is a lost frame");
  describe(root.write(layout::kFlags, flags_), "", "V4L2_BUF_FLAG_* of each frame's buffer");
  describe(root.write(layout::kContrast, scores_), "grey levels", "live contact score (docs/capture.md); NaN where the frame did not decode");
  write_header(root, header_);
  write_trailer(root, trailer, timestamps_.size());
  frames_.reset();
  file_->commit();
}

PressFile::PressFile(std::string path) : path_(std::move(path)), file_(open_checked(path_, Kind::press)) {
  const h5::Group root = file_.root();
  frames_ = root.open_dataset(layout::kFrames);
  if (!is_vlen_bytes(frames_)) throw input_error(path_, frames_.object_path(), "expected variable-length uint8 frames", "Record the press again");
  encoding_ = root.attr_string(layout::kEncoding);
  if (encoding_ != "jpeg" && encoding_ != "png")
    throw input_error(path_, "/", "unknown frame encoding '" + encoding_ + "'", "Expected jpeg or png");
  const std::int64_t width = root.attr_int(layout::kWidth), height = root.attr_int(layout::kHeight);
  // 65535: V4L2 frame sizes; anything else is a damaged attribute, not a frame size.
  if (width <= 0 || height <= 0 || width > 65535 || height > 65535)
    throw input_error(path_, "/@width, /@height", std::to_string(width) + " x " + std::to_string(height) + " is not a frame size",
                      "Record the press again");
  // A few MB may declare 30000 x 30000 frames and a /reference of that size: refused before any is read (review 12, F1).
  if (std::uint64_t(width) * std::uint64_t(height) > kMaxImagePixels)
    throw input_error(path_, "/@width, /@height", std::to_string(width) + " x " + std::to_string(height) +
                                                      " is over 64 megapixels, larger than any press haptex reads",
                      "Record the press again at the sensor's own frame size");
  size_ = cv::Size(int(width), int(height));
  fps_ = root.attr_double(layout::kFps);
  if (fps_ != 0 && !(fps_ >= kLowestFps && fps_ <= kHighestFps))  // 0: not known (replay then needs fps=)
    throw input_error(path_, "/@fps", text::format("is %g, neither 0 (not known) nor a frame rate of %g to %g frames per second",
                                                   fps_, kLowestFps, kHighestFps),
                      "Record the press again, or replay it with replay:FILE,fps=N");
  count_ = frames_.shape().at(0);
  require_consistent_frames(root);
}

// What the recorder stated of the frames agrees with them (review 9, F7: a /@samples of 1e12, a
// /timestamp_ns of 10 values for 46 frames, a /@peak_frame of 99999 were replayed and extracted).
void PressFile::refuse(const std::string& where, const std::string& what) const {
  throw input_error(path_, where, what, "The file is damaged or was not written by haptex capture record: record the press again");
}

void PressFile::require_consistent_frames(const h5::Group& root) const {
  const std::int64_t frames = std::int64_t(count_);
  if (const std::int64_t samples = root.attr_int(layout::kSamples); samples != frames)
    refuse("/@samples", "is " + std::to_string(samples) + ", but /frames holds " + std::to_string(frames));
  for (const char* per_frame : {layout::kTimestampNs, layout::kSequence, layout::kFlags, layout::kContrast}) {
    if (!root.has_dataset(per_frame)) continue;
    if (const h5::Shape shape = root.open_dataset(per_frame).shape(); shape != h5::Shape{count_})
      refuse(std::string("/") + per_frame,
             "has shape " + h5::shape_text(shape) + ", not one value for each of the " + std::to_string(frames) + " frames");
  }
  for (const char* index : {layout::kContactFirst, layout::kContactLast, layout::kPeakFrame})
    if (const std::int64_t i = root.attr_int(index); i < -1 || i >= frames)
      refuse(std::string("/@") + index, "is " + std::to_string(i) + ", not a frame of the " + std::to_string(frames) + " (or -1: none)");
  const std::int64_t first = root.attr_int(layout::kContactFirst), last = root.attr_int(layout::kContactLast);
  if (first >= 0 && last >= 0 && last < first)
    refuse("/@contact_last", "is " + std::to_string(last) + ", before /@contact_first (" + std::to_string(first) + ")");
  require_frame_order(root);
  require_control_lists(root);
  require_reference_shape(root);
}

// Review 9, F7: stamps that run backwards and a counter that counts down were replayed and extracted.
// CLOCK_MONOTONIC never repeats or runs back between two frames; 0 is a frame the driver gave no time.
// The counter may stand still (a driver that does not count) and wraps at 2^32, but never runs back.
void PressFile::require_frame_order(const h5::Group& root) const {
  if (root.has_dataset(layout::kTimestampNs)) {
    std::int64_t previous = 0;
    const std::vector<std::int64_t> stamps = root.open_dataset(layout::kTimestampNs).read<std::int64_t>();
    for (std::size_t i = 0; i < stamps.size(); ++i) {
      if (stamps[i] == 0) continue;
      if (stamps[i] <= previous)
        refuse(std::string("/") + layout::kTimestampNs + "[" + std::to_string(i) + "]",
               "is " + std::to_string(stamps[i]) + " ns, not after the frame before (" + std::to_string(previous) + " ns)");
      previous = stamps[i];
    }
  }
  if (root.has_dataset(layout::kSequence)) {
    const std::vector<std::uint32_t> sequence = root.open_dataset(layout::kSequence).read<std::uint32_t>();
    for (std::size_t i = 1; i < sequence.size(); ++i)
      if (std::uint32_t(sequence[i] - sequence[i - 1]) >= 0x80000000u)
        refuse(std::string("/") + layout::kSequence + "[" + std::to_string(i) + "]",
               "is " + std::to_string(sequence[i]) + " after " + std::to_string(sequence[i - 1]) +
                   ": the frame counter runs back (a jump of 2^31 or more, counted modulo 2^32 as the counter wraps)");
  }
}

// locked_controls: a JSON array of objects; missing_controls: a JSON array of names (schemas/hdf5-layout.md).
void PressFile::require_control_lists(const h5::Group& root) const {
  for (const auto& [name, element] : {std::pair{layout::kLockedControls, nlohmann::json::value_t::object},
                                      std::pair{layout::kMissingControls, nlohmann::json::value_t::string}}) {
    const nlohmann::json list = nlohmann::json::parse(root.attr_string(name), nullptr, false);
    const bool right = list.is_array() && std::all_of(list.begin(), list.end(), [&](const nlohmann::json& e) { return e.type() == element; });
    if (!right)
      refuse(std::string("/@") + name, element == nlohmann::json::value_t::object ? "is not a JSON array of controls"
                                                                                  : "is not a JSON array of control names");
  }
}

// The reference's shape, checked when the file opens: replay never reads its pixels, yet a file whose
// reference is not the frame size is damaged all the same.
void PressFile::require_reference_shape(const h5::Group& root) const {
  const h5::Dataset d = root.open_dataset(layout::kReference);
  const h5::Shape shape = d.shape();
  if (shape.size() != 3 || shape[2] != 3 || d.dtype() != "uint8")
    throw input_error(path_, d.object_path(), "expected an H x W x 3 uint8 image", "Was the file written by haptex?");
  if (cv::Size(int(shape[1]), int(shape[0])) != size_)
    throw input_error(path_, d.object_path(), "the reference is not the frame size", "Record the press again");
}

std::vector<std::uint8_t> PressFile::bytes(std::size_t index) const { return read_vlen_bytes(frames_, index); }

cv::Mat PressFile::reference() const {
  const h5::Group root = file_.root();
  const ChannelOrder order = read_channel_order(root, layout::kReference);
  const std::vector<std::uint8_t> pixels = root.open_dataset(layout::kReference).read<std::uint8_t>();
  cv::Mat image(size_, CV_8UC3);  // the file's opening checked the shape
  std::memcpy(image.data, pixels.data(), pixels.size());
  if (order == ChannelOrder::rgb) cv::cvtColor(image, image, cv::COLOR_RGB2BGR);
  return image;
}

}  // namespace haptex::dataset
