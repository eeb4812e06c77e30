#include "synth/gelsight_presses.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "core/error.hpp"
#include "core/random_seeds.hpp"

namespace haptex::synth {
namespace {

double unit(std::mt19937_64& engine) { return unit_draw(engine); }

}  // namespace

PressPlan plan_press(std::uint64_t material_seed, int press, double period_mm, const MaterialPressOptions& options) {
  std::mt19937_64 engine(derive_seed(material_seed, 0x9e55, std::uint64_t(press)));
  PressPlan plan;
  plan.press = press;
  const int count = std::max(options.presses, 1);
  plan.pose.x_mm = period_mm * (press + 0.25 + 0.5 * unit(engine)) / count;
  plan.pose.y_mm = period_mm * unit(engine);
  const double tilt = options.max_tilt * (0.3 + 0.7 * unit(engine)), direction = 2 * std::numbers::pi * unit(engine);
  plan.pose.tilt_x = tilt * std::cos(direction);
  plan.pose.tilt_y = tilt * std::sin(direction);
  plan.timeline = make_press_timeline(engine(), options.timeline);
  plan.noise_seed = engine();
  return plan;
}

PressSidecar write_press(const GelSightRenderer& renderer, const PressPlan& plan, const std::string& directory,
                         const std::string& material, const std::string& source) {
  const PressTimeline& timeline = plan.timeline;
  PressVideoWriter writer(directory, plan.press, timeline.fps);
  const cv::Mat surface = renderer.surface_under(plan.pose);
  cv::Mat shaded;
  double shaded_depth = -1;
  for (int f = 0; f < timeline.frames(); ++f) {
    const double depth = timeline.depth_mm[std::size_t(f)];
    if (depth != shaded_depth) {
      shaded = renderer.shade(surface, depth);
      shaded_depth = depth;
    }
    writer.add(renderer.expose(shaded, timeline.exposure_gain[std::size_t(f)], derive_seed(plan.noise_seed, std::uint64_t(f))));
  }
  PressSidecar sidecar;
  sidecar.material = material;
  sidecar.press = plan.press;
  sidecar.fps = timeline.fps;
  sidecar.peak_frame = timeline.peak_frame;
  sidecar.contact_first = timeline.contact_first;
  sidecar.contact_last = timeline.contact_last;
  sidecar.peak_depth_mm = timeline.peak_depth_mm();
  sidecar.location_mm = std::array<double, 2>{plan.pose.x_mm, plan.pose.y_mm};
  sidecar.source = source;
  return writer.finish(sidecar);
}

std::vector<PressSidecar> write_material_presses(const GelSightRenderer& renderer, const std::string& directory,
                                                 const std::string& material, std::uint64_t seed,
                                                 const std::string& source, const MaterialPressOptions& options) {
  if (options.presses < 1) throw failure("write_material_presses: at least one press");
  std::vector<PressSidecar> sidecars;
  for (int j = 0; j < options.presses; ++j)
    sidecars.push_back(write_press(renderer, plan_press(seed, j, renderer.period_mm(), options), directory, material, source));
  return sidecars;
}

}  // namespace haptex::synth
