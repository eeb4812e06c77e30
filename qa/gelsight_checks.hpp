#pragma once
// gelsight.* (docs/qa.md, "GelSight presses"): every press of a gelsight or dataset file is read
// once (qa/press_data.hpp); each check_gelsight_* function is one check of the catalog, judging all
// of them.
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <opencv2/core.hpp>

#include "qa/check.hpp"
#include "qa/press_data.hpp"

namespace haptex::qa {

// Per image size (one sensor mode), what the file's no-contact references look like: their per-pixel
// median scoring image (only with kMinReferencesForMedian or more) and their median sharpness.
using ImageSize = std::pair<int, int>;  // width, height
struct NoContactBaselines {
  std::map<ImageSize, cv::Mat> reference;
  std::map<ImageSize, double> sharpness;
};
NoContactBaselines no_contact_baselines(const std::vector<Press>& presses);

CheckResult check_gelsight_reference(const std::vector<Press>& presses, const NoContactBaselines& baselines);
CheckResult check_gelsight_peak_score(const std::vector<Press>& presses);
CheckResult check_gelsight_saturation(const std::vector<Press>& presses);
CheckResult check_gelsight_blur(const std::vector<Press>& presses, const NoContactBaselines& baselines);
CheckResult check_gelsight_resolution(const GelsightPresses& file);
CheckResult check_gelsight_press_count(const std::map<std::string, std::size_t>& per_material);
CheckResult check_gelsight_source_damage(const std::vector<Press>& presses);
// The same press of the same source twice (a video given twice, or through a link or a copy).
CheckResult check_gelsight_duplicate(const h5::Group& root);
CheckResult check_gelsight_channel_order(const h5::Group& root);
CheckResult check_gelsight_frame_numbers(const h5::Group& root);
// dataset::require_whole_press_images on every image, the check merge and align run on every shard.
CheckResult check_gelsight_images(const h5::Group& root);

}  // namespace haptex::qa
