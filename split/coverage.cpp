#include "split/coverage.hpp"

#include <opencv2/imgproc.hpp>

namespace haptex::split {

double hull_coverage(const std::vector<cv::Point2f>& train, const std::vector<cv::Point2f>& points) {
  if (points.empty()) return 1.0;
  if (train.size() < 3) return 0.0;
  std::vector<cv::Point2f> hull;
  cv::convexHull(train, hull);
  if (hull.size() < 3) return 0.0;
  std::size_t inside = 0;
  for (const cv::Point2f& p : points)
    if (cv::pointPolygonTest(hull, p, false) >= 0) ++inside;
  return double(inside) / double(points.size());
}

}  // namespace haptex::split
