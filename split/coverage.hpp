#pragma once
// Whether validation and test ask the model about actions it was trained on: the share of their
// (speed, force) points inside the convex hull of the training points (docs/split.md).
#include <opencv2/core.hpp>
#include <vector>

namespace haptex::split {

// Points on the hull's boundary count as inside. With fewer than three distinct training points
// there is no area, and nothing is covered.
double hull_coverage(const std::vector<cv::Point2f>& train, const std::vector<cv::Point2f>& points);

}  // namespace haptex::split
