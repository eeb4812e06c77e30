#pragma once
// A synthetic material's GelSight presses, end to end: each press gets its own place on the surface,
// tilt, timeline and noise from the material's seed, is rendered frame by frame and written as a
// press video (synth/press_video_writer.hpp). `haptex synth materials` writes
// OUT/gelsight/<Material>/press_<j>/ and press_<j>.json this way.
#include <cstdint>
#include <string>
#include <vector>

#include "synth/gelsight_renderer.hpp"
#include "synth/press_timeline.hpp"
#include "synth/press_video_writer.hpp"

namespace haptex::synth {

struct MaterialPressOptions {
  int presses = 5;
  PressTimelineOptions timeline;
  double max_tilt = 0.004;  // the surface's largest slope relative to the gel (mm per mm, ~0.23 degrees)
};

struct PressPlan {
  int press = 0;
  PressPose pose;
  PressTimeline timeline;
  std::uint64_t noise_seed = 0;
};

// Press j's pose, timeline and noise seed. Presses spread over the periodic surface: their x offsets
// are evenly spaced (jittered), their y offsets scattered.
PressPlan plan_press(std::uint64_t material_seed, int press, double period_mm, const MaterialPressOptions& options = {});

// Renders a planned press and writes it into `directory`. Frames of equal consecutive depth (the
// no-contact ones) share one shading. Returns the sidecar written.
PressSidecar write_press(const GelSightRenderer& renderer, const PressPlan& plan, const std::string& directory,
                         const std::string& material, const std::string& source);

// Presses 0 .. options.presses - 1 of one material. Deterministic for a seed.
std::vector<PressSidecar> write_material_presses(const GelSightRenderer& renderer, const std::string& directory,
                                                 const std::string& material, std::uint64_t seed,
                                                 const std::string& source, const MaterialPressOptions& options = {});

}  // namespace haptex::synth
