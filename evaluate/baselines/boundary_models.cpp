#include "evaluate/baselines/boundary_models.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.hpp"

namespace haptex::evaluate {
namespace {

// HaTT's grid step: max / 5 rounded down to a multiple of `unit`; for a range too small for one
// unit, max / 5 itself (the published files never need this; small synthetic ones do).
double grid_step(double max, double unit) {
  const double step = unit * std::floor(max / (5.0 * unit));
  return step > 0.0 ? step : max / 5.0;
}

void check_maxima(double max_speed, double max_force) {
  if (!(max_speed > 0.0) || !(max_force > 0.0) || !std::isfinite(max_speed) || !std::isfinite(max_force))
    throw failure("HaTT boundary models: the maximum speed and force must be finite and positive (got " +
                  std::to_string(max_speed) + " mm/s, " + std::to_string(max_force) + " N)");
}

// The forces 0.5, 0.5 + f, ... strictly inside the speed = 0 and speed = max edges.
std::vector<double> edge_forces(double max_force) {
  const double step = grid_step(max_force, 0.25);
  std::vector<double> forces;
  for (int k = 0;; ++k) {
    const double force = 0.5 + k * step;
    if (force > max_force - step + 1e-9) break;
    forces.push_back(force);
  }
  return forces;
}

std::size_t nearest_model(const ar::ModelSet& set, std::size_t fitted, double speed, double force) {
  std::size_t best = 0;
  double best_distance = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < fitted; ++i) {
    const double d = std::hypot(set.speed_list[i] - speed, set.force_list[i] - force);
    if (d < best_distance) best_distance = d, best = i;
  }
  return best;
}

bool coincides(const ar::ModelSet& set, std::size_t fitted, const BoundaryVertex& v) {
  for (std::size_t i = 0; i < fitted; ++i)
    if (std::abs(set.speed_list[i] - v.speed) <= 1e-6 * set.max_speed &&
        std::abs(set.force_list[i] - v.force) <= 1e-6 * set.max_force)
      return true;
  return false;
}

}  // namespace

std::vector<BoundaryVertex> hatt_boundary_vertices(double max_speed, double max_force) {
  check_maxima(max_speed, max_force);
  const double s = grid_step(max_speed, 5.0);
  const std::vector<double> forces = edge_forces(max_force);
  std::vector<BoundaryVertex> out;
  for (int k = 0; k <= 4; ++k) out.push_back({k * s, 0.0, true});
  out.push_back({max_speed, 0.0, true});
  for (double f : forces) out.push_back({0.0, f, true});
  out.push_back({0.0, max_force, true});
  for (double f : forces) out.push_back({max_speed, f, false});
  out.push_back({max_speed, max_force, false});
  for (int k = 1; k <= 4; ++k) out.push_back({k * s, max_force, false});
  return out;
}

void add_hatt_boundary_models(ar::ModelSet& set) {
  if (set.models.empty() || set.speed_list.size() != set.models.size() || set.force_list.size() != set.models.size())
    throw failure("HaTT boundary models: the set needs its fitted models, with one speed and force each, first");
  const std::size_t fitted = set.models.size();
  int number = 0;
  for (const ar::ArModel& m : set.models) number = std::max(number, m.number);
  for (const BoundaryVertex& v : hatt_boundary_vertices(set.max_speed, set.max_force)) {
    if (coincides(set, fitted, v)) continue;
    ar::ArModel copy = set.models[nearest_model(set, fitted, v.speed, v.force)];
    copy.number = ++number;
    copy.speed = v.speed;
    copy.force = v.force;
    if (v.silent) copy.variance = 0.0;
    set.models.push_back(std::move(copy));
    set.speed_list.push_back(v.speed);
    set.force_list.push_back(v.force);
  }
}

}  // namespace haptex::evaluate
