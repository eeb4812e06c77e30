#include "synth/press_timeline.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "core/error.hpp"
#include "core/random_seeds.hpp"

namespace haptex::synth {
namespace {

// Uniform draws written out here (not std::uniform_*_distribution, whose algorithms are unspecified),
// so a seed means the same press with every standard library.
struct Draw {
  std::mt19937_64 engine;
  double unit() { return unit_draw(engine); }  // [0, 1)
  double between(double lo, double hi) { return lo + (hi - lo) * unit(); }
  int integer(int lo, int hi) { return lo + int(engine() % std::uint64_t(hi - lo + 1)); }  // [lo, hi]
};

// Share of the peak depth reached at the end of the ramp and the start of the release. The hold stays
// within 10 % of the peak, and its frames next to the peak are 5 % shallower: the deepest frame is
// then also the one that differs most from the no-contact image, as the ground truth needs.
constexpr double kHoldFloor = 0.9;

// From 0 (exclusive) up to kHoldFloor x peak (inclusive) along a smooth S curve in `frames` steps,
// or from below it back towards 0 (exclusive).
void append_ramp(std::vector<double>& depth, int frames, double peak, bool rising) {
  for (int i = 1; i <= frames; ++i) {
    const double t = rising ? double(i) / frames : double(frames - i + 1) / (frames + 1);
    const double s = std::sin(0.5 * std::numbers::pi * t);
    depth.push_back(peak * kHoldFloor * s * s);
  }
}

// The hold: from kHoldFloor up to exactly the peak in its middle frame and back, in equal steps.
void append_hold(std::vector<double>& depth, int frames, double peak) {
  const int middle = frames / 2, reach = std::max(middle, frames - 1 - middle);
  for (int i = 0; i < frames; ++i) {
    const double offset = double(std::abs(i - middle)) / reach;  // 0 at the peak, 1 at the far end
    depth.push_back(peak * (1 - (1 - kHoldFloor) * offset));
  }
}

// A half-cosine from gain 1 to 1 + drift: slow, smooth and monotonic, as a sensor warming up.
std::vector<double> exposure_drift(int frames, double drift) {
  std::vector<double> gain(std::size_t(frames), 1.0);
  for (int i = 0; i < frames; ++i)
    gain[std::size_t(i)] = 1 + drift * 0.5 * (1 - std::cos(std::numbers::pi * i / std::max(frames - 1, 1)));
  return gain;
}

}  // namespace

PressTimeline make_press_timeline(std::uint64_t seed, const PressTimelineOptions& options) {
  if (!(options.fps > 0) || options.lead_frames < 1 || !(options.peak_depth_mm > 0) ||
      !(options.peak_jitter >= 0 && options.peak_jitter < 1) || !(options.max_drift >= 0))
    throw failure("make_press_timeline: fps, lead frames and peak depth must be positive, jitter in [0, 1)");
  Draw draw{std::mt19937_64(seed)};
  const int lead = options.lead_frames + draw.integer(0, 2);
  const int ramp = draw.integer(6, 9), hold = draw.integer(3, 5), release = draw.integer(4, 6), tail = draw.integer(3, 4);
  const double peak = options.peak_depth_mm * draw.between(1 - options.peak_jitter, 1 + options.peak_jitter);
  const double drift = options.max_drift * draw.between(0.4, 1.0) * (draw.unit() < 0.5 ? -1 : 1);

  PressTimeline timeline;
  timeline.fps = options.fps;
  timeline.depth_mm.assign(std::size_t(lead), 0.0);
  append_ramp(timeline.depth_mm, ramp, peak, true);
  append_hold(timeline.depth_mm, hold, peak);
  append_ramp(timeline.depth_mm, release, peak, false);
  timeline.depth_mm.resize(timeline.depth_mm.size() + std::size_t(tail), 0.0);
  timeline.exposure_gain = exposure_drift(timeline.frames(), drift);
  timeline.contact_first = lead;
  timeline.contact_last = lead + ramp + hold + release - 1;
  timeline.peak_frame = lead + ramp + hold / 2;
  return timeline;
}

}  // namespace haptex::synth
