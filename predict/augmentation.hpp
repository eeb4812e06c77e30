#pragma once
// The 8 training variants of a GelSight frame (docs/predict.md): the four 90-degree rotations,
// each with and without mirroring, i.e. the symmetries of the square. A texture has no preferred
// orientation on the sensor, so all 8 are equally real images of it.
#include <vector>

#include <opencv2/core.hpp>

namespace haptex::predict {

constexpr int kAugmentations = 8;

// variant 0..7: mirrored left-right first when variant >= 4, then rotated by (variant % 4) x 90
// degrees counter-clockwise. Variant 0 is the image itself. Rotations by 90 and 270 degrees swap
// width and height.
cv::Mat augment(const cv::Mat& image, int variant);
std::vector<cv::Mat> all_augmentations(const cv::Mat& image);

}  // namespace haptex::predict
