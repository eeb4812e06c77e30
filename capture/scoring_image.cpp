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
  if (frame.channels() == 1) return to_scoring(frame, frame.size());
  cv::Mat grey;
  cv::cvtColor(frame, grey, frame.channels() == 4 ? cv::COLOR_BGRA2GRAY : cv::COLOR_BGR2GRAY);
  return to_scoring(grey, frame.size());
}

cv::Mat scoring_image_from_jpeg(std::span<const std::uint8_t> jpeg, cv::Size frame) {
  if (jpeg.size() < 4) return {};
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
