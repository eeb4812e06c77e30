#include "capture/extraction/contact_sheet.hpp"
#include "media/codecs.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace haptex::capture {
namespace {

constexpr int kPanelWidth = 320, kTitleHeight = 30, kLabelHeight = 22;
const cv::Scalar kWhite(255, 255, 255), kBlack(0, 0, 0);

void text(cv::Mat& image, const std::string& s, cv::Point at, double scale = 0.45, const cv::Scalar& colour = kBlack) {
  cv::putText(image, s, at, cv::FONT_HERSHEY_SIMPLEX, scale, colour, 1, cv::LINE_AA);
}

cv::Mat panel(const cv::Mat& image, int height, const std::string& label) {
  cv::Mat out(height + kLabelHeight, kPanelWidth, CV_8UC3, kWhite);
  cv::Mat scaled;
  cv::resize(image, scaled, {kPanelWidth, height}, 0, 0, cv::INTER_AREA);
  scaled.copyTo(out(cv::Rect(0, kLabelHeight, kPanelWidth, height)));
  text(out, label, {6, 16});
  return out;
}

cv::Mat difference(const cv::Mat& peak, const cv::Mat& reference) {
  cv::Mat d, grey, coloured;
  cv::absdiff(peak, reference, d);
  cv::cvtColor(d, grey, cv::COLOR_BGR2GRAY);
  grey.convertTo(grey, CV_8U, 4.0);  // presses change a few grey levels; x4 makes them visible
  cv::applyColorMap(grey, coloured, cv::COLORMAP_INFERNO);
  return coloured;
}

}  // namespace

cv::Mat contact_sheet(const ContactSheetInput& in) {
  const int height = std::max(1, int(std::lround(double(kPanelWidth) * in.peak.rows / in.peak.cols)));
  std::vector<cv::Mat> row = {panel(in.reference, height, "reference (no contact)"),
                              panel(in.peak, height, "peak: frame " + std::to_string(in.peak_index)),
                              panel(difference(in.peak, in.reference), height, "|peak - reference| x4")};
  cv::Mat panels;
  cv::hconcat(row, panels);
  cv::Mat title(kTitleHeight, panels.cols, CV_8UC3, kWhite);
  text(title, in.title, {6, 20}, 0.5);
  cv::Mat sheet;
  cv::vconcat(std::vector<cv::Mat>{title, panels, score_chart(in.chart, panels.cols)}, sheet);
  return sheet;
}

std::vector<std::uint8_t> contact_sheet_png(const ContactSheetInput& input) {
  std::vector<std::uint8_t> png;
  media::encode_image(".png", contact_sheet(input), png);
  return png;
}

}  // namespace haptex::capture
