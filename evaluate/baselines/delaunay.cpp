#include "evaluate/baselines/delaunay.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>

#include <opencv2/imgproc.hpp>

#include "core/error.hpp"

namespace haptex::evaluate {
namespace {

// Subdiv2D works in float pixel-like coordinates inside an integer rectangle: the unit square
// becomes [0, kSide]^2. Subdiv2D starts from a finite triangle of virtual vertices three rectangle
// sizes away, and a triangle on the hull whose circumcircle reaches one of them is replaced by
// triangles to it (so lost): the rectangle is made 10^4 times the points' square, which keeps
// every hull triangle whose third vertex is more than ~1e-6 of the range from the hull edge.
constexpr double kSide = 1000.0;
constexpr int kMargin = 10'000'000;
// Points are snapped to 1/1024 pixel (about 1e-6 of the range): closer points are one vertex, so
// Subdiv2D's own epsilon never silently merges two points we count as distinct.
constexpr double kSnap = 1024.0;

using Key = std::pair<float, float>;

struct Distinct {
  std::vector<cv::Point2f> points;         // scaled, snapped, each once
  std::map<Key, std::size_t> first_index;  // scaled point -> first input index
};

double snapped(double value, double low, double extent) {
  const double unit = extent > 0.0 ? (value - low) / extent : 0.0;
  return std::round(unit * kSide * kSnap) / kSnap;
}

Distinct scale_and_deduplicate(std::span<const double> x, std::span<const double> y) {
  const auto [x_low, x_high] = std::minmax_element(x.begin(), x.end());
  const auto [y_low, y_high] = std::minmax_element(y.begin(), y.end());
  Distinct out;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const cv::Point2f p(float(snapped(x[i], *x_low, *x_high - *x_low)), float(snapped(y[i], *y_low, *y_high - *y_low)));
    if (out.first_index.emplace(Key{p.x, p.y}, i).second) out.points.push_back(p);
  }
  return out;
}

// Twice the signed area of (a, b, c), in double so float coordinates lose nothing.
double cross(const cv::Point2f& a, const cv::Point2f& b, const cv::Point2f& c) {
  return (double(b.x) - a.x) * (double(c.y) - a.y) - (double(c.x) - a.x) * (double(b.y) - a.y);
}

double hull_area(const std::vector<cv::Point2f>& points) {
  std::vector<cv::Point2f> hull;
  cv::convexHull(points, hull);
  return hull.size() < 3 ? 0.0 : cv::contourArea(hull);
}

// Subdiv2D's triangles name coordinates, not vertex ids; those that touch its virtual outer
// vertices (far outside the rectangle) have no index and are dropped.
std::vector<std::array<std::size_t, 3>> indexed_triangles(const Distinct& d, const std::vector<cv::Vec6f>& list,
                                                          double& area) {
  std::vector<std::array<std::size_t, 3>> out;
  area = 0.0;
  for (const cv::Vec6f& t : list) {
    std::array<std::size_t, 3> tri{};
    std::array<cv::Point2f, 3> p;
    bool known = true;
    for (std::size_t k = 0; k < 3 && known; ++k) {
      p[k] = cv::Point2f(t[2 * k], t[2 * k + 1]);
      const auto found = d.first_index.find(Key{p[k].x, p[k].y});
      known = found != d.first_index.end();
      if (known) tri[k] = found->second;
    }
    const double twice_area = known ? cross(p[0], p[1], p[2]) : 0.0;
    if (twice_area == 0.0) continue;  // virtual vertex, or a sliver of collinear points
    if (twice_area < 0.0) std::swap(tri[1], tri[2]);
    area += 0.5 * std::abs(twice_area);
    out.push_back(tri);
  }
  return out;
}

void check_result(const Distinct& d, const std::vector<std::array<std::size_t, 3>>& triangles, double area,
                  double hull) {
  std::vector<bool> used(d.first_index.size(), false);
  std::map<std::size_t, std::size_t> slot;  // first input index -> position in `used`
  for (const auto& [key, index] : d.first_index) slot.emplace(index, slot.size());
  for (const auto& tri : triangles)
    for (std::size_t v : tri) used[slot.at(v)] = true;
  const auto missing = std::count(used.begin(), used.end(), false);
  if (missing > 0)
    throw failure("Delaunay triangulation: " + std::to_string(missing) + " of " + std::to_string(used.size()) +
                  " points are in no triangle (OpenCV Subdiv2D lost them); the model set cannot be built");
  if (std::abs(area - hull) > 1e-6 * hull)
    throw failure("Delaunay triangulation: the triangles cover " + std::to_string(area) + " of the convex hull's " +
                  std::to_string(hull) + " (scaled units); the model set cannot be built");
}

}  // namespace

std::vector<std::array<std::size_t, 3>> delaunay_triangles(std::span<const double> x, std::span<const double> y) {
  if (x.size() != y.size())
    throw failure("Delaunay triangulation: " + std::to_string(x.size()) + " x values but " + std::to_string(y.size()) +
                  " y values; give one of each per point");
  for (std::size_t i = 0; i < x.size(); ++i)
    if (!std::isfinite(x[i]) || !std::isfinite(y[i]))
      throw failure("Delaunay triangulation: point " + std::to_string(i) + " is not finite");
  if (x.size() < 3) return {};
  const Distinct d = scale_and_deduplicate(x, y);
  const double hull = hull_area(d.points);
  if (d.points.size() < 3 || hull <= 1e-9 * kSide * kSide) return {};
  cv::Subdiv2D subdiv(cv::Rect(-kMargin, -kMargin, 2 * kMargin, 2 * kMargin));
  subdiv.insert(d.points);
  std::vector<cv::Vec6f> list;
  subdiv.getTriangleList(list);
  double area = 0.0;
  auto triangles = indexed_triangles(d, list, area);
  check_result(d, triangles, area, hull);
  return triangles;
}

}  // namespace haptex::evaluate
