#pragma once
// Free-hand circular strokes as a person makes them on a texture with a haptic probe: circles of
// varying radius, pace and direction, slowing to a brief dwell where a stroke turns. Speed and
// force wander smoothly and are steered towards the parts of the (speed, force) plane visited
// least so far, so one recording covers the plane up to the given maxima.
#include <cstdint>
#include <vector>

namespace haptex::synth {

struct StrokeLimits {
  double max_speed_mm_s = 200;
  double max_force_n = 4;
};

struct StrokeOptions {
  double seconds = 10;
  double sample_rate_hz = 10000;
};

// One recording's hand motion, one value per sample: tangential speed (mm/s), normal force (N),
// tool position (mm; z follows the force through the probe's compliance).
struct Strokes {
  std::vector<double> speed, force, position_x, position_y, position_z;
};

Strokes generate_strokes(const StrokeLimits& limits, const StrokeOptions& options, std::uint64_t seed);

// Share of the rectangle [0, max_speed] x [0, max_force], cut into cells x cells, holding at least
// one (speed, force) sample: how completely the strokes cover the model's operating range.
double operating_range_coverage(const std::vector<const Strokes*>& strokes, const StrokeLimits& limits, int cells = 10);

}  // namespace haptex::synth
