#pragma once
// One PNG per press for a person to check at a glance: the no-contact reference, the peak frame,
// their difference, and the source's contact score over time with the press marked.
#include <cstdint>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "capture/extraction/score_chart.hpp"

namespace haptex::capture {

struct ContactSheetInput {
  std::string title;              // material, press and source
  cv::Mat reference, peak;        // BGR, same size
  std::int64_t peak_index = 0;
  ScoreChart chart;               // the source's scores with this press, its stored range and kept frames
};

cv::Mat contact_sheet(const ContactSheetInput& input);  // BGR image
// Encodes the sheet as PNG bytes.
std::vector<std::uint8_t> contact_sheet_png(const ContactSheetInput& input);

}  // namespace haptex::capture
