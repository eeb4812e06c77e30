#include "capture/extraction/score_chart.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "core/text/format.hpp"
#include "media/codecs.hpp"

namespace haptex::capture {
namespace {

constexpr int kPlotHeight = 230, kTitleHeight = 30;
const cv::Scalar kWhite(255, 255, 255), kBlack(0, 0, 0), kGrey(150, 150, 150), kRed(40, 40, 220), kBlue(200, 120, 30),
    kRange(235, 225, 210), kContact(200, 230, 250), kReference(215, 240, 215);

void text(cv::Mat& image, const std::string& s, cv::Point at, double scale = 0.45, const cv::Scalar& colour = kBlack) {
  cv::putText(image, s, at, cv::FONT_HERSHEY_SIMPLEX, scale, colour, 1, cv::LINE_AA);
}

}  // namespace

cv::Mat score_chart(const ScoreChart& in, int width) {
  cv::Mat plot(kPlotHeight, width, CV_8UC3, kWhite);
  const int left = 50, right = width - 15, top = 15, bottom = kPlotHeight - 35;
  const std::int64_t n = std::max<std::int64_t>(2, std::int64_t(in.scores.size()));
  float top_score = std::max(in.trigger, 1e-3f);
  for (float s : in.scores)
    if (!std::isnan(s)) top_score = std::max(top_score, s);
  top_score *= 1.1f;
  const auto x_of = [&](double frame) { return left + int(std::lround((right - left) * frame / double(n - 1))); };
  const auto y_of = [&](double score) { return bottom - int(std::lround((bottom - top) * score / top_score)); };
  const auto shade = [&](std::int64_t first, std::int64_t last, const cv::Scalar& colour) {
    if (first >= 0) cv::rectangle(plot, {x_of(double(first)), top}, {x_of(double(last)), bottom}, colour, cv::FILLED);
  };

  shade(in.reference_first, in.reference_last, kReference);
  shade(in.range_first, in.range_last, kRange);
  for (const auto& p : in.presses) shade(p.first, p.last, kContact);
  for (float level : {in.trigger, in.release})
    for (int x = left; x < right; x += 8) cv::line(plot, {x, y_of(level)}, {std::min(x + 4, right), y_of(level)}, kGrey);
  for (int x = left; x < right; x += 4) cv::line(plot, {x, y_of(in.level)}, {x, y_of(in.level)}, kBlue);
  for (std::int64_t k : in.kept) cv::line(plot, {x_of(double(k)), bottom}, {x_of(double(k)), bottom + 6}, kBlue, 2);
  for (std::size_t i = 1; i < in.scores.size(); ++i) {
    const float a = in.scores[i - 1], b = in.scores[i];
    if (std::isnan(a) || std::isnan(b)) continue;
    cv::line(plot, {x_of(double(i - 1)), y_of(a)}, {x_of(double(i)), y_of(b)}, kBlack, 1, cv::LINE_AA);
  }
  for (const auto& p : in.presses) {
    cv::line(plot, {x_of(double(p.peak)), top}, {x_of(double(p.peak)), bottom}, kRed, 1);
    text(plot, "peak " + std::to_string(p.peak), {std::min(x_of(double(p.peak)) + 4, right - 80), top + 14}, 0.4, kRed);
  }
  cv::rectangle(plot, {left, top}, {right, bottom}, kGrey);
  text(plot, "0", {left - 4, bottom + 20}, 0.4);
  text(plot, std::to_string(n - 1), {right - 24, bottom + 20}, 0.4);
  text(plot, "frame", {left + 14, bottom + 20}, 0.4);
  text(plot, text::format("%.2f", double(top_score / 1.1f)), {4, top + 10}, 0.35);
  text(plot, "0", {30, bottom}, 0.35);
  text(plot, "score", {4, (top + bottom) / 2}, 0.35);
  std::string legend = "green: reference  orange: contact  ";
  if (in.range_first >= 0) legend += "blue: stored range  ticks: kept frames  ";
  legend += "dashed: trigger, release  dotted: no-contact level";
  int baseline = 0;
  const int legend_width = cv::getTextSize(legend, cv::FONT_HERSHEY_SIMPLEX, 0.35, 1, &baseline).width;
  text(plot, legend, {std::max(left, right - legend_width), bottom + 28}, 0.35, kGrey);
  text(plot, in.caption, {left + 4, top - 3}, 0.35, kGrey);
  return plot;
}

std::vector<std::uint8_t> score_chart_png(const std::string& title, const ScoreChart& chart, int width) {
  cv::Mat heading(kTitleHeight, width, CV_8UC3, kWhite);
  text(heading, title, {6, 20}, 0.5);
  cv::Mat image;
  cv::vconcat(std::vector<cv::Mat>{heading, score_chart(chart, width)}, image);
  std::vector<std::uint8_t> png;
  media::encode_image(".png", image, png);
  return png;
}

}  // namespace haptex::capture
