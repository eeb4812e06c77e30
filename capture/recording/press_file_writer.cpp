#include "capture/recording/press_file_writer.hpp"

#include <linux/videodev2.h>

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "capture/device/fourcc.hpp"
#include "media/codecs.hpp"

namespace haptex::capture {

dataset::PressFileHeader press_file_header(std::uint32_t fourcc, int width, int height) {
  dataset::PressFileHeader h;
  h.fourcc = fourcc_text(fourcc);
  const bool jpeg = fourcc == V4L2_PIX_FMT_MJPEG;
  h.encoding = jpeg ? "jpeg" : "png";
  h.frames_description = jpeg ? "one JPEG per frame, the bytes the sensor sent (MJPG), not re-encoded"
                              : "one lossless PNG per frame, converted from the sensor's " + fourcc_text(fourcc);
  h.width = width;
  h.height = height;
  return h;
}

PressFileWriter::PressFileWriter(const std::string& path, const dataset::PressFileHeader& header, const cv::Mat& reference)
    : jpeg_(header.encoding == "jpeg"), size_(header.width, header.height), file_(path, header, reference), drops_(1e9 / header.fps) {
  summary_.path = path;
}

std::vector<std::uint8_t> PressFileWriter::stored(const Frame& frame) const {
  if (jpeg_) return frame.bytes;
  std::vector<std::uint8_t> png;
  if (frame.bytes.size() != std::size_t(size_.area()) * 2) return png;  // a cut-off raw frame: kept empty
  const cv::Mat yuyv(size_, CV_8UC2, const_cast<std::uint8_t*>(frame.bytes.data()));
  cv::Mat bgr;
  cv::cvtColor(yuyv, bgr, cv::COLOR_YUV2BGR_YUYV);
  media::encode_image(".png", bgr, png, {cv::IMWRITE_PNG_COMPRESSION, 1});
  return png;
}

void PressFileWriter::append(const Frame& frame, float score, std::uint64_t error_buffers) {
  if (file_.frames() == 0) summary_.first_sequence = frame.sequence;
  else summary_.error_frames += error_buffers;
  summary_.last_sequence = frame.sequence;
  if (std::isnan(score)) ++summary_.corrupt_frames;
  drops_.observe(frame.sequence, frame.timestamp_ns, error_buffers);
  file_.append(stored(frame), frame.timestamp_ns, frame.sequence, frame.flags, score);
}

void PressFileWriter::mark_contact(std::int64_t first, std::int64_t last, std::int64_t peak) {
  summary_.contact_first = first;
  summary_.contact_last = last;
  summary_.peak = peak;
}

PressFileSummary PressFileWriter::finish(const std::string& ended_by) {
  summary_.frames = file_.frames();
  summary_.dropped_frames = drops_.dropped();
  summary_.ended_by = ended_by;
  file_.finish({summary_.dropped_frames, summary_.error_frames, summary_.corrupt_frames, summary_.contact_first,
                summary_.contact_last, summary_.peak, ended_by});
  return summary_;
}

}  // namespace haptex::capture
