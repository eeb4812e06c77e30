#pragma once
// One PNG per press for a person to check at a glance: the no-contact reference, the peak frame,
// their difference, and the source's contact score over time with the press marked.
#include <cstdint>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace haptex::capture {

struct ContactSheetInput {
  std::string title;              // material, press and source
  cv::Mat reference, peak;        // BGR, same size
  std::vector<float> scores;      // the whole source, NaN where there is no score
  std::int64_t range_first = 0, range_last = 0;      // the press's stored frames
  std::int64_t contact_first = 0, contact_last = 0;  // contact
  std::int64_t peak_index = 0;
  std::vector<std::int64_t> kept;  // the frames kept for the dataset
  float trigger = 0, release = 0, level = 0;  // level: the no-contact score the trigger stands above
  std::string detection;  // the thresholds and signal-to-noise in words (extract_presses.hpp, describe)
};

cv::Mat contact_sheet(const ContactSheetInput& input);  // BGR image
// Encodes the sheet as PNG bytes.
std::vector<std::uint8_t> contact_sheet_png(const ContactSheetInput& input);

}  // namespace haptex::capture
