#include "capture/recording/press_file_writer.hpp"

#include <linux/videodev2.h>

#include <cmath>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "capture/device/fourcc.hpp"
#include "capture/storage/image_datasets.hpp"
#include "core/naming.hpp"
#include "dataset/channel_order.hpp"
#include "dataset/format.hpp"
#include "dataset/layout.hpp"

namespace haptex::capture {

namespace layout = dataset::layout;
namespace {

void describe(h5::Dataset dataset, const std::string& units, const std::string& description) {
  if (!units.empty()) dataset.set_attr("units", units);
  dataset.set_attr("description", description);
}

}  // namespace

PressFileWriter::PressFileWriter(const std::string& path, const PressFileInfo& info, const cv::Mat& reference)
    : info_(info), file_(std::make_unique<h5::AtomicFile>(path, false)), drops_(1e9 / info.fps) {
  h5::Group root = file_->root();
  frames_ = std::make_unique<dataset::VlenBytesWriter>(root, layout::kFrames);
  describe(frames_->dataset(), "",
           info.fourcc == V4L2_PIX_FMT_MJPEG ? "one JPEG per frame, the bytes the sensor sent (MJPG), not re-encoded"
                                             : "one lossless PNG per frame, converted from the sensor's " + fourcc_text(info.fourcc));
  write_image(root, layout::kReference, reference, "no-contact reference: mean of the frames taken before the presses");
  summary_.path = path;
}

std::vector<std::uint8_t> PressFileWriter::encode(const Frame& frame) const {
  if (info_.fourcc == V4L2_PIX_FMT_MJPEG) return frame.bytes;
  std::vector<std::uint8_t> png;
  if (frame.bytes.size() != std::size_t(info_.width) * info_.height * 2) return png;  // a cut-off raw frame: kept empty
  const cv::Mat yuyv(info_.height, info_.width, CV_8UC2, const_cast<std::uint8_t*>(frame.bytes.data()));
  cv::Mat bgr;
  cv::cvtColor(yuyv, bgr, cv::COLOR_YUV2BGR_YUYV);
  cv::imencode(".png", bgr, png, {cv::IMWRITE_PNG_COMPRESSION, 1});
  return png;
}

void PressFileWriter::append(const Frame& frame, float score, std::uint64_t error_buffers) {
  const std::vector<std::uint8_t> bytes = encode(frame);
  frames_->append(bytes);
  if (timestamps_.empty()) summary_.first_sequence = frame.sequence;
  summary_.last_sequence = frame.sequence;
  if (!timestamps_.empty()) summary_.error_frames += error_buffers;
  if (std::isnan(score)) ++summary_.corrupt_frames;
  drops_.observe(frame.sequence, frame.timestamp_ns, error_buffers);
  timestamps_.push_back(frame.timestamp_ns);
  sequences_.push_back(frame.sequence);
  flags_.push_back(frame.flags);
  scores_.push_back(score);
}

void PressFileWriter::mark_contact(std::int64_t first, std::int64_t last, std::int64_t peak) {
  summary_.contact_first = first;
  summary_.contact_last = last;
  summary_.peak = peak;
}

PressFileSummary PressFileWriter::finish(const std::string& ended_by) {
  summary_.frames = timestamps_.size();
  summary_.dropped_frames = drops_.dropped();
  summary_.ended_by = ended_by;
  h5::Group root = file_->root();
  describe(root.write("timestamp_ns", timestamps_), "ns", "CLOCK_MONOTONIC time the driver stamped on each frame");
  describe(root.write("sequence", sequences_), "", "the driver's frame counter; a gap is a lost frame");
  describe(root.write("flags", flags_), "", "V4L2_BUF_FLAG_* of each frame's buffer");
  describe(root.write(layout::kContrast, scores_), "grey levels",
           "live contact score (docs/capture.md); NaN where the frame did not decode");
  dataset::stamp(root, dataset::Kind::press, info_.provenance);
  root.set_attr("samples", std::int64_t(summary_.frames));
  root.set_attr("material", info_.material);
  root.set_attr("material_id", material_id(info_.material));
  root.set_attr("press_index", info_.press_index);
  root.set_attr("device", info_.device);
  root.set_attr("card", info_.card);
  root.set_attr("driver", info_.driver);
  root.set_attr("bus_info", info_.bus_info);
  root.set_attr("serial", info_.serial);
  root.set_attr("fourcc", fourcc_text(info_.fourcc));
  root.set_attr("encoding", info_.fourcc == V4L2_PIX_FMT_MJPEG ? "jpeg" : "png");
  // JPEG and PNG decode to R, G, B; the reference is written RGB (storage/image_datasets.hpp).
  root.set_attr(layout::kChannelOrder, dataset::channel_order_name(dataset::kWrittenChannelOrder));
  root.set_attr("width", info_.width);
  root.set_attr("height", info_.height);
  root.set_attr("fps", info_.fps);
  root.set_attr("requested_fps", info_.requested_fps);
  root.set_attr("locked_controls", info_.locked_controls);
  root.set_attr("missing_controls", info_.missing_controls);
  root.set_attr("dropped_frames", std::int64_t(summary_.dropped_frames));
  root.set_attr("error_frames", std::int64_t(summary_.error_frames));
  root.set_attr("corrupt_frames", std::int64_t(summary_.corrupt_frames));
  root.set_attr("contact_first", summary_.contact_first);
  root.set_attr("contact_last", summary_.contact_last);
  root.set_attr("peak_frame", summary_.peak);
  root.set_attr("ended_by", ended_by);
  root.set_attr("noise", double(info_.noise));
  root.set_attr("pixel_threshold", double(info_.pixel_threshold));
  root.set_attr("trigger", double(info_.trigger));
  root.set_attr(layout::kNoContactLevel, double(info_.level));
  frames_.reset();
  file_->commit();
  return summary_;
}

}  // namespace haptex::capture
