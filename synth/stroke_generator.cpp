#include "synth/stroke_generator.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace haptex::synth {
namespace {

constexpr int kCells = 10;               // steering grid over the (speed, force) rectangle
constexpr double kCompliance = 0.02;     // mm of tool travel per N (probe tip into the surface)

double smoothstep(double t) {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * (3 - 2 * t);
}

class CoverageGrid {
 public:
  explicit CoverageGrid(const StrokeLimits& limits) : limits_(limits), visits_(kCells * kCells, 0) {}
  void visit(double speed, double force) { ++visits_[index(speed, force)]; }
  // The least-visited of a few random cells, as a (speed, force) target inside it.
  std::pair<double, double> pick_target(std::mt19937_64& rng) const {
    std::uniform_int_distribution<int> cell(0, kCells * kCells - 1);
    std::uniform_real_distribution<double> unit(0, 1);
    int best = cell(rng);
    for (int i = 0; i < 11; ++i) {
      const int candidate = cell(rng);
      if (visits_[std::size_t(candidate)] < visits_[std::size_t(best)]) best = candidate;
    }
    const double speed = (best % kCells + unit(rng)) * limits_.max_speed_mm_s / kCells;
    const double force = (best / kCells + unit(rng)) * limits_.max_force_n / kCells;
    return {speed, force};
  }

 private:
  std::size_t index(double speed, double force) const {
    const int s = std::clamp(int(speed / limits_.max_speed_mm_s * kCells), 0, kCells - 1);
    const int f = std::clamp(int(force / limits_.max_force_n * kCells), 0, kCells - 1);
    return std::size_t(f * kCells + s);
  }
  StrokeLimits limits_;
  std::vector<int> visits_;
};

// One stroke: a dwell at the turn, a smooth ramp up to the target pace, a wandering hold, and a
// ramp down into the next turn; force glides from where it was to its target over the stroke.
struct Stroke {
  double seconds, dwell, ramp_up, ramp_down, start_speed, end_speed, target_speed, from_force, target_force;
  double wander_hz, wander_phase;

  double speed_at(double t) const {
    const double wander = 1 + 0.08 * std::sin(2 * std::numbers::pi * wander_hz * t + wander_phase);
    const double up = smoothstep((t - dwell) / ramp_up), down = smoothstep((seconds - t) / ramp_down);
    const double rising = start_speed + (target_speed * wander - start_speed) * up;
    return end_speed + (rising - end_speed) * down;
  }
  double force_at(double t) const {
    const double glide = smoothstep(t / (0.7 * seconds));
    // Zero at t = 0, so the force flows on from the previous stroke without a step.
    const double wander = 1 + 0.04 * (std::sin(2 * std::numbers::pi * 0.7 * wander_hz * t + 2 * wander_phase) -
                                      std::sin(2 * wander_phase));
    return (from_force + (target_force - from_force) * glide) * wander;
  }
};

Stroke next_stroke(std::mt19937_64& rng, const CoverageGrid& grid, double from_force, double from_speed) {
  std::uniform_real_distribution<double> unit(0, 1);
  const auto [speed, force] = grid.pick_target(rng);
  Stroke s{};
  s.seconds = 0.35 + 0.45 * unit(rng);
  s.dwell = 0.03 + 0.07 * unit(rng);
  s.ramp_up = 0.1 + 0.1 * unit(rng);
  s.ramp_down = 0.1 + 0.1 * unit(rng);
  s.start_speed = from_speed;
  s.end_speed = 0.5 + 2.5 * unit(rng);  // the slow turn into the next stroke
  s.target_speed = speed;
  s.from_force = from_force;
  s.target_force = force;
  s.wander_hz = 1 + 3 * unit(rng);
  s.wander_phase = 2 * std::numbers::pi * unit(rng);
  return s;
}

}  // namespace

Strokes generate_strokes(const StrokeLimits& limits, const StrokeOptions& options, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  CoverageGrid grid(limits);
  const std::size_t n = std::size_t(std::llround(options.seconds * options.sample_rate_hz));
  const double dt = 1.0 / options.sample_rate_hz;
  Strokes out;
  for (auto* v : {&out.speed, &out.force, &out.position_x, &out.position_y, &out.position_z}) v->reserve(n);

  double force = limits.max_force_n * (0.2 + 0.3 * unit(rng)), speed = 1.0;
  double heading = 2 * std::numbers::pi * unit(rng), x = 0, y = 0;
  int direction = 1;
  while (out.speed.size() < n) {
    const Stroke stroke = next_stroke(rng, grid, force, speed);
    if (unit(rng) < 0.5) direction = -direction;  // the hand reverses its circle at some turns
    const double radius = 5 + 20 * unit(rng);
    for (double t = 0; t < stroke.seconds && out.speed.size() < n; t += dt) {
      speed = std::clamp(stroke.speed_at(t), 0.0, limits.max_speed_mm_s);
      force = std::clamp(stroke.force_at(t), 0.0, limits.max_force_n);
      heading += direction * speed / radius * dt;
      x += speed * std::cos(heading) * dt;
      y += speed * std::sin(heading) * dt;
      out.speed.push_back(speed);
      out.force.push_back(force);
      out.position_x.push_back(x);
      out.position_y.push_back(y);
      out.position_z.push_back(-kCompliance * force);
      grid.visit(speed, force);
    }
  }
  return out;
}

double operating_range_coverage(const std::vector<const Strokes*>& strokes, const StrokeLimits& limits, int cells) {
  std::vector<bool> hit(std::size_t(cells * cells), false);
  for (const Strokes* s : strokes)
    for (std::size_t i = 0; i < s->speed.size(); ++i) {
      const int a = std::clamp(int(s->speed[i] / limits.max_speed_mm_s * cells), 0, cells - 1);
      const int b = std::clamp(int(s->force[i] / limits.max_force_n * cells), 0, cells - 1);
      hit[std::size_t(b * cells + a)] = true;
    }
  return double(std::count(hit.begin(), hit.end(), true)) / double(hit.size());
}

}  // namespace haptex::synth
