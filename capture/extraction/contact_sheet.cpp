#include "capture/extraction/contact_sheet.hpp"
#include "core/text/format.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace haptex::capture {
namespace {

constexpr int kPanelWidth = 320, kPlotHeight = 230, kTitleHeight = 30, kLabelHeight = 22;
const cv::Scalar kWhite(255, 255, 255), kBlack(0, 0, 0), kGrey(150, 150, 150), kRed(40, 40, 220),
    kBlue(200, 120, 30), kRange(235, 225, 210), kContact(200, 230, 250);

void text(cv::Mat& image, const std::string& s, cv::Point at, double scale = 0.45, const cv::Scalar& colour = kBlack) {
  cv::putText(image, s, at, cv::FONT_HERSHEY_SIMPLEX, scale, colour, 1, cv::LINE_AA);
}

std::string number(double value, int digits = 2) {
  return text::format("%.*f", digits, value);
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

// The score curve: x is the frame, y the score; the press's range and contact shaded, the kept
// frames ticked, the peak in red, the trigger and release levels dashed.
cv::Mat score_plot(const ContactSheetInput& in, int width) {
  cv::Mat plot(kPlotHeight, width, CV_8UC3, kWhite);
  const int left = 50, right = width - 15, top = 15, bottom = kPlotHeight - 35;
  const std::int64_t n = std::max<std::int64_t>(2, std::int64_t(in.scores.size()));
  float top_score = std::max(in.trigger, 1e-3f);
  for (float s : in.scores)
    if (!std::isnan(s)) top_score = std::max(top_score, s);
  top_score *= 1.1f;
  const auto x_of = [&](double frame) { return left + int(std::lround((right - left) * frame / double(n - 1))); };
  const auto y_of = [&](double score) { return bottom - int(std::lround((bottom - top) * score / top_score)); };

  cv::rectangle(plot, {x_of(double(in.range_first)), top}, {x_of(double(in.range_last)), bottom}, kRange, cv::FILLED);
  cv::rectangle(plot, {x_of(double(in.contact_first)), top}, {x_of(double(in.contact_last)), bottom}, kContact, cv::FILLED);
  for (float level : {in.trigger, in.release})
    for (int x = left; x < right; x += 8) cv::line(plot, {x, y_of(level)}, {std::min(x + 4, right), y_of(level)}, kGrey);
  for (int x = left; x < right; x += 4) cv::line(plot, {x, y_of(in.level)}, {x, y_of(in.level)}, kBlue);
  for (std::int64_t k : in.kept) cv::line(plot, {x_of(double(k)), bottom}, {x_of(double(k)), bottom + 6}, kBlue, 2);
  for (std::size_t i = 1; i < in.scores.size(); ++i) {
    const float a = in.scores[i - 1], b = in.scores[i];
    if (std::isnan(a) || std::isnan(b)) continue;
    cv::line(plot, {x_of(double(i - 1)), y_of(a)}, {x_of(double(i)), y_of(b)}, kBlack, 1, cv::LINE_AA);
  }
  cv::line(plot, {x_of(double(in.peak_index)), top}, {x_of(double(in.peak_index)), bottom}, kRed, 1);
  cv::rectangle(plot, {left, top}, {right, bottom}, kGrey);
  text(plot, "0", {left - 4, bottom + 20}, 0.4);
  text(plot, std::to_string(n - 1), {right - 24, bottom + 20}, 0.4);
  text(plot, "peak " + std::to_string(in.peak_index), {std::min(x_of(double(in.peak_index)) + 4, right - 80), top + 14}, 0.4, kRed);
  text(plot, "frame", {left + 40, bottom + 28}, 0.4);
  text(plot, number(top_score / 1.1f), {4, top + 10}, 0.35);
  text(plot, "0", {30, bottom}, 0.35);
  text(plot, "score", {4, (top + bottom) / 2}, 0.35);
  text(plot, "orange: contact  blue: stored range  ticks: kept frames  dashed: trigger, release  dotted: no-contact level",
       {right - 700, bottom + 28}, 0.35, kGrey);
  text(plot, in.detection, {left + 4, top - 3}, 0.35, kGrey);
  return plot;
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
  cv::vconcat(std::vector<cv::Mat>{title, panels, score_plot(in, panels.cols)}, sheet);
  return sheet;
}

std::vector<std::uint8_t> contact_sheet_png(const ContactSheetInput& input) {
  std::vector<std::uint8_t> png;
  cv::imencode(".png", contact_sheet(input), png);
  return png;
}

}  // namespace haptex::capture
