#include "capture/recording/press_file_writer.hpp"

#include <linux/videodev2.h>

#include <cmath>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "capture/device/fourcc.hpp"
#include "capture/storage/image_datasets.hpp"
#include "core/naming.hpp"
#include "dataset/channel_order.hpp"
#include "dataset/description.hpp"
#include "dataset/format.hpp"
#include "dataset/layout.hpp"

namespace haptex::capture {

namespace layout = dataset::layout;

PressFileWriter::PressFileWriter(const std::string& path, const PressFileInfo& info, const cv::Mat& reference)
    : info_(info), file_(std::make_unique<h5::AtomicFile>(path, false)), drops_(1e9 / info.fps) {
  h5::Group root = file_->root();
  frames_ = std::make_unique<dataset::VlenBytesWriter>(root, layout::kFrames);
  dataset::describe(frames_->dataset(), "",
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
  dataset::describe(root.write(layout::kTimestampNs, timestamps_), "ns", "CLOCK_MONOTONIC time the driver stamped on each frame");
  dataset::describe(root.write(layout::kSequence, sequences_), "", "the driver's frame counter; a gap is a lost frame");
  dataset::describe(root.write(layout::kFlags, flags_), "", "V4L2_BUF_FLAG_* of each frame's buffer");
  dataset::describe(root.write(layout::kContrast, scores_), "grey levels",
           "live contact score (docs/capture.md); NaN where the frame did not decode");
  dataset::stamp(root, dataset::Kind::press, info_.provenance);
  root.set_attr(layout::kSamples, std::int64_t(summary_.frames));
  root.set_attr(layout::kPressMaterial, info_.material);
  root.set_attr(layout::kPressMaterialId, material_id(info_.material));
  root.set_attr(layout::kPressIndex, info_.press_index);
  root.set_attr(layout::kDevice, info_.device);
  root.set_attr(layout::kCard, info_.card);
  root.set_attr(layout::kDriver, info_.driver);
  root.set_attr(layout::kBusInfo, info_.bus_info);
  root.set_attr(layout::kSerial, info_.serial);
  root.set_attr(layout::kFourcc, fourcc_text(info_.fourcc));
  root.set_attr(layout::kEncoding, info_.fourcc == V4L2_PIX_FMT_MJPEG ? "jpeg" : "png");
  // JPEG and PNG decode to R, G, B; the reference is written RGB (storage/image_datasets.hpp).
  root.set_attr(layout::kChannelOrder, dataset::channel_order_name(dataset::kWrittenChannelOrder));
  root.set_attr(layout::kWidth, info_.width);
  root.set_attr(layout::kHeight, info_.height);
  root.set_attr(layout::kFps, info_.fps);
  root.set_attr(layout::kRequestedFps, info_.requested_fps);
  root.set_attr(layout::kLockedControls, info_.locked_controls);
  root.set_attr(layout::kMissingControls, info_.missing_controls);
  root.set_attr(layout::kDroppedFrames, std::int64_t(summary_.dropped_frames));
  root.set_attr(layout::kErrorFrames, std::int64_t(summary_.error_frames));
  root.set_attr(layout::kCorruptFrames, std::int64_t(summary_.corrupt_frames));
  root.set_attr(layout::kContactFirst, summary_.contact_first);
  root.set_attr(layout::kContactLast, summary_.contact_last);
  root.set_attr(layout::kPeakFrame, summary_.peak);
  root.set_attr(layout::kEndedBy, ended_by);
  root.set_attr(layout::kNoise, double(info_.noise));
  root.set_attr(layout::kPixelThreshold, double(info_.pixel_threshold));
  root.set_attr(layout::kTrigger, double(info_.trigger));
  root.set_attr(layout::kNoContactLevel, double(info_.level));
  frames_.reset();
  file_->commit();
  return summary_;
}

}  // namespace haptex::capture
