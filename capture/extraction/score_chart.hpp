#pragma once
// A source's contact score over time, drawn for a person: the no-contact reference's frames, the
// no-contact level, the trigger and release, and each press (contact shaded, peak in red). The
// contact sheets draw it for one press; `capture extract --explain` for every source, pressed or not.
#include <cstdint>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace haptex::capture {

struct ScoreChart {
  struct Press {
    std::int64_t first = 0, last = 0, peak = 0;  // contact frames, inclusive, and the peak
  };
  std::vector<float> scores;  // the whole source, NaN where there is no score
  float level = 0, trigger = 0, release = 0;
  std::int64_t reference_first = -1, reference_last = -1;  // the reference's frames; -1: an image
  std::vector<Press> presses;
  std::int64_t range_first = -1, range_last = -1;  // a press's stored frames (contact sheets); -1: none
  std::vector<std::int64_t> kept;                  // the frames kept for the dataset (ticks)
  std::string caption;                             // the thresholds in words, above the plot
};

// BGR image `width` pixels wide.
cv::Mat score_chart(const ScoreChart& chart, int width);

// A titled chart as PNG bytes (capture extract --explain).
std::vector<std::uint8_t> score_chart_png(const std::string& title, const ScoreChart& chart, int width = 960);

}  // namespace haptex::capture
