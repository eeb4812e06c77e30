#include "evaluate/baselines/ar_segments.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>

#include "core/error.hpp"

namespace haptex::evaluate {
namespace {

// HaTT's renderer treats speeds and forces under 0.05 as zero (piecewise_model.cpp); a model
// there would sit on the silent edges the boundary models already hold.
constexpr double kAtRest = 0.05;

// MATLAB's median: the mean of the two middle values for an even count.
double median(std::vector<double> v) {
  const auto middle = v.begin() + std::ptrdiff_t(v.size() / 2);
  std::nth_element(v.begin(), middle, v.end());
  if (v.size() % 2 == 1) return *middle;
  return 0.5 * (*middle + *std::max_element(v.begin(), middle));
}

double median_of(std::span<const double> x) { return median(std::vector<double>(x.begin(), x.end())); }

// Nothing to fit: no vibration at all, or a sample the recording lost (NaN, infinity).
bool silent(std::span<const double> accel, std::span<const double> force, std::span<const double> speed) {
  bool any_motion = false;
  for (std::size_t i = 0; i < accel.size(); ++i) {
    if (!std::isfinite(accel[i]) || !std::isfinite(force[i]) || !std::isfinite(speed[i])) return true;
    any_motion = any_motion || accel[i] != 0.0;
  }
  return !any_motion;
}

void cut_piece(const TrainingPiece& piece, std::size_t index, std::size_t length, SegmentCut& out) {
  for (std::size_t start = 0; start + length <= piece.accel.size(); start += length) {
    const auto accel = piece.accel.subspan(start, length);
    const auto force = piece.force.subspan(start, length);
    const auto speed = piece.speed.subspan(start, length);
    if (silent(accel, force, speed)) {
      ++out.silent;
      continue;
    }
    const LabelledSegment s{index, start, median_of(speed), median_of(force)};
    if (s.speed < kAtRest || s.force < kAtRest) {
      ++out.at_rest;
      continue;
    }
    out.segments.push_back(s);
  }
}

// Labels scaled to [0, 1] over their bounding box (0 on an axis with no extent).
struct Box {
  double speed_low, speed_extent, force_low, force_extent;
  double u(double speed) const { return speed_extent > 0.0 ? (speed - speed_low) / speed_extent : 0.0; }
  double v(double force) const { return force_extent > 0.0 ? (force - force_low) / force_extent : 0.0; }
};

Box bounding_box(std::span<const LabelledSegment> segments) {
  const auto [s_low, s_high] = std::minmax_element(segments.begin(), segments.end(),
                                                   [](const auto& a, const auto& b) { return a.speed < b.speed; });
  const auto [f_low, f_high] = std::minmax_element(segments.begin(), segments.end(),
                                                   [](const auto& a, const auto& b) { return a.force < b.force; });
  return {s_low->speed, s_high->speed - s_low->speed, f_low->force, f_high->force - f_low->force};
}

std::size_t cell_of(double unit, std::size_t cells) { return std::min(cells - 1, std::size_t(unit * double(cells))); }

void place(SegmentGroup& group, std::span<const LabelledSegment> segments) {
  std::vector<double> speeds, forces;
  for (std::size_t m : group.members) speeds.push_back(segments[m].speed), forces.push_back(segments[m].force);
  group.speed = median(std::move(speeds));
  group.force = median(std::move(forces));
}

}  // namespace

SegmentCut cut_segments(std::span<const TrainingPiece> pieces, std::size_t length) {
  if (length == 0) throw failure("AR segments: the segment length must be at least one sample");
  SegmentCut out;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const TrainingPiece& p = pieces[i];
    if (p.force.size() != p.accel.size() || p.speed.size() != p.accel.size())
      throw failure("AR segments: training piece " + std::to_string(i) + " has " + std::to_string(p.accel.size()) +
                    " acceleration, " + std::to_string(p.force.size()) + " force and " + std::to_string(p.speed.size()) +
                    " speed samples; give the three signals of one section over the same samples");
    out.total_samples += p.accel.size();
    out.longest_piece = std::max(out.longest_piece, p.accel.size());
    cut_piece(p, i, length, out);
  }
  return out;
}

std::vector<SegmentGroup> group_segments(std::span<const LabelledSegment> segments, std::size_t cells_per_axis) {
  if (segments.empty()) throw failure("AR segments: there are no segments to group");
  if (cells_per_axis == 0) throw failure("AR segments: the grid needs at least one cell per axis");
  const Box box = bounding_box(segments);
  std::map<std::pair<std::size_t, std::size_t>, std::vector<std::size_t>> cells;  // (force row, speed column)
  for (std::size_t i = 0; i < segments.size(); ++i)
    cells[{cell_of(box.v(segments[i].force), cells_per_axis), cell_of(box.u(segments[i].speed), cells_per_axis)}]
        .push_back(i);
  std::vector<SegmentGroup> groups;
  for (const auto& [cell, members] : cells) {
    groups.push_back({members, 0.0, 0.0});
    place(groups.back(), segments);
  }
  return groups;
}

}  // namespace haptex::evaluate
