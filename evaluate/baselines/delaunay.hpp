#pragma once
// Delaunay triangulation of (speed, force) vertices for a piecewise AR model set, with OpenCV's
// cv::Subdiv2D. Speed (hundreds of mm/s) and force (a few N) differ by two orders of magnitude, so
// each axis is first scaled to [0, 1] over the points' bounding box: HaTT's own triangles match a
// Delaunay triangulation of (speed / maxSpeed, force / maxForce), not of the raw values.
#include <array>
#include <cstddef>
#include <span>
#include <vector>

namespace haptex::evaluate {

// Triangles as 0-based indices into x / y, counter-clockwise in the scaled plane. A point given
// twice is triangulated once, under its first index (later copies appear in no triangle). Returns
// no triangles when the points span no area (fewer than three, or all on one line). Throws
// haptex::Error when x and y differ in length or hold a non-finite value, and when the result
// fails its own checks (every distinct point a vertex, the triangles tiling the convex hull).
std::vector<std::array<std::size_t, 3>> delaunay_triangles(std::span<const double> x, std::span<const double> y);

}  // namespace haptex::evaluate
