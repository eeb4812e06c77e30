#include "capture/recording/delivered_rate.hpp"
#include "core/text/format.hpp"

#include <cmath>
#include <cstdio>

namespace haptex::capture {
namespace {

std::string fixed(double value, int decimals) {
  return text::format("%.*f", decimals, value);
}

}  // namespace

void DeliveredRate::observe(std::int64_t timestamp_ns) {
  if (frames_++ == 0) first_ns_ = timestamp_ns;
  last_ns_ = timestamp_ns;
}

std::optional<double> DeliveredRate::fps() const {
  if (frames_ < kMinRateIntervals + 1 || last_ns_ <= first_ns_) return std::nullopt;
  return double(frames_ - 1) / span_seconds();
}

std::string slow_delivery_warning(const SlowDelivery& t) {
  if (t.granted_fps <= 0 || t.delivered_fps >= (1 - kSlowRateMargin) * t.granted_fps) return "";
  const double short_percent = 100 * (1 - t.delivered_fps / t.granted_fps);
  std::string text = t.node + ": the sensor delivered " + fixed(t.delivered_fps, 1) + " frames per second (" +
                     std::to_string(t.frames) + " frames in " + fixed(t.span_seconds, 1) +
                     " s by the driver's timestamps), " + fixed(short_percent, 0) + " % below the " +
                     fixed(t.granted_fps, t.granted_fps == std::round(t.granted_fps) ? 0 : 2) + " fps it granted";
  std::string lost;
  if (t.dropped_frames > 0) lost = std::to_string(t.dropped_frames) + " frames lost";
  if (t.error_buffers > 0) lost += (lost.empty() ? "" : ", ") + std::to_string(t.error_buffers) + " buffers flagged as errors";
  if (!lost.empty()) text += " (" + lost + ")";
  // exposure_time_absolute counts 100 us units.
  const long period_units = std::lround(1e4 / t.granted_fps);
  return text + ". Usual causes: a USB link that cannot carry the mode ('haptex capture devices' shows its speed; "
                "try another port, --format MJPG or a smaller --size), or an exposure longer than a frame period (" +
         fixed(1000 / t.granted_fps, 0) + " ms: keep --control exposure_time_absolute below " + std::to_string(period_units) + ")";
}

}  // namespace haptex::capture
