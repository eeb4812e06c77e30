#include "capture/extraction/gel_image.hpp"

#include <opencv2/imgproc.hpp>

#include "capture/extraction/peak_frames.hpp"
#include "core/error.hpp"
#include "core/text/format.hpp"

namespace haptex::capture {

void require_gel_image(const cv::Mat& bgr, const std::string& file, const std::string& where, const std::string& fix) {
  cv::Mat grey;
  cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
  cv::Scalar mean, spread;
  cv::meanStdDev(grey, mean, spread);
  if (mean[0] < kBlackLevel)
    throw input_error(file, where, text::format("is black (a mean grey of %.3g of 255), no frame of a lit sensor", mean[0]), fix);
  if (spread[0] < 1.0)
    throw input_error(file, where, text::format("is one flat grey (%.3g of 255 everywhere), no frame of a sensor's gel", mean[0]), fix);
}

}  // namespace haptex::capture
