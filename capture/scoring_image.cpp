#include "capture/scoring_image.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace haptex::capture {
namespace {

constexpr int kScoringWidth = 160;

int block_factor(cv::Size frame) { return std::max(1, int(std::lround(double(frame.width) / kScoringWidth))); }

cv::Mat to_scoring(const cv::Mat& grey, cv::Size frame) {
  cv::Mat small, out;
  const cv::Size size = scoring_size(frame);
  if (grey.size() == size) small = grey;
  else cv::resize(grey, small, size, 0, 0, cv::INTER_AREA);
  small.convertTo(out, CV_32F);
  return out;
}

}  // namespace

cv::Size scoring_size(cv::Size frame) {
  const int f = block_factor(frame);
  return {std::max(1, frame.width / f), std::max(1, frame.height / f)};
}

int jpeg_reduction(cv::Size frame) {
  const int f = block_factor(frame);
  return f >= 8 ? 8 : f >= 4 ? 4 : f >= 2 ? 2 : 1;
}

cv::Mat scoring_image(const cv::Mat& frame) {
  cv::Mat grey = frame;
  if (frame.channels() != 1) cv::cvtColor(frame, grey, frame.channels() == 4 ? cv::COLOR_BGRA2GRAY : cv::COLOR_BGR2GRAY);
  // The same two steps as reduced JPEG decoding (r x r blocks first, then the rest), so a frame
  // scores the same whichever way it was decoded.
  const int r = jpeg_reduction(frame.size());
  if (r > 1) {
    cv::Mat reduced;
    cv::resize(grey, reduced, {(frame.cols + r - 1) / r, (frame.rows + r - 1) / r}, 0, 0, cv::INTER_AREA);
    grey = reduced;
  }
  return to_scoring(grey, frame.size());
}

bool is_complete_jpeg(std::span<const std::uint8_t> jpeg) {
  if (jpeg.size() < 4 || jpeg[0] != 0xFF || jpeg[1] != 0xD8) return false;
  const std::size_t tail = std::min<std::size_t>(jpeg.size(), 4096);
  for (std::size_t i = jpeg.size() - 1; i + tail > jpeg.size() && i > 0; --i)
    if (jpeg[i - 1] == 0xFF && jpeg[i] == 0xD9) return true;
  return false;
}

cv::Mat scoring_image_from_jpeg(std::span<const std::uint8_t> jpeg, cv::Size frame) {
  if (!is_complete_jpeg(jpeg)) return {};
  const int r = jpeg_reduction(frame);
  const int flag = r == 8 ? cv::IMREAD_REDUCED_GRAYSCALE_8
                 : r == 4 ? cv::IMREAD_REDUCED_GRAYSCALE_4
                 : r == 2 ? cv::IMREAD_REDUCED_GRAYSCALE_2
                          : cv::IMREAD_GRAYSCALE;
  const cv::Mat bytes(1, int(jpeg.size()), CV_8U, const_cast<std::uint8_t*>(jpeg.data()));
  cv::Mat grey;
  try {
    grey = cv::imdecode(bytes, flag);
  } catch (const cv::Exception&) {
    return {};
  }
  // DCT scaling rounds up: 3280 / 8 -> 410.
  const cv::Size expected((frame.width + r - 1) / r, (frame.height + r - 1) / r);
  if (grey.empty() || grey.size() != expected) return {};
  return to_scoring(grey, frame);
}

cv::Mat scoring_image_from_yuyv(std::span<const std::uint8_t> yuyv, cv::Size frame) {
  if (yuyv.size() != std::size_t(frame.width) * frame.height * 2) return {};
  const cv::Mat packed(frame.height, frame.width, CV_8UC2, const_cast<std::uint8_t*>(yuyv.data()));
  cv::Mat grey;
  cv::extractChannel(packed, grey, 0);
  return to_scoring(grey, frame);
}

}  // namespace haptex::capture
