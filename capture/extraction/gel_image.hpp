#pragma once
// A no-contact reference must be a frame of a lit gel: not black (a mean grey under kBlackLevel of
// 255), not one flat grey (no texture of a gel in it). Checked where a reference comes in: a
// --reference image and the one a press file stores (review 6; review 10, F6: a stored reference of
// all 255 was used, every frame then counted as contact).
#include <opencv2/core.hpp>
#include <string>

namespace haptex::capture {

// Throws haptex::Error (bad_input) naming `file` and `where` (empty, or "/reference") with `fix`.
void require_gel_image(const cv::Mat& bgr, const std::string& file, const std::string& where, const std::string& fix);

}  // namespace haptex::capture
