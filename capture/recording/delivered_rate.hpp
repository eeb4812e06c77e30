#pragma once
// The frame rate a take actually delivered, measured from the driver's timestamps, and the warning
// when it falls clearly short of the rate the driver granted: a sensor on a link too slow for its
// mode, or exposing longer than a frame period, keeps its granted rate on paper and sends fewer
// frames (GelSight Mini users on Linux get 15-18 of 25 fps), which press files would otherwise hide.
#include <cstdint>
#include <optional>
#include <string>

namespace haptex::capture {

// Below this many intervals between frames a take is too short to judge.
inline constexpr std::uint64_t kMinRateIntervals = 20;
// A take is slow when it delivered less than (1 - kSlowRateMargin) x the granted rate. 10 %: far
// above what timing adds (timestamps jitter by about a millisecond over spans of seconds, sensor
// clocks by parts per million) and above an occasional lost frame (a few percent, which the drop
// counts report anyway); far below the shortfalls users meet (18.75 of 25 fps is 25 % short).
inline constexpr double kSlowRateMargin = 0.10;

class DeliveredRate {
 public:
  void observe(std::int64_t timestamp_ns);
  std::uint64_t frames() const { return frames_; }
  // From the first frame's timestamp to the last's.
  double span_seconds() const { return double(last_ns_ - first_ns_) * 1e-9; }
  // (frames - 1) / span: the intervals, so a steady sensor measures its exact rate. nullopt below
  // kMinRateIntervals intervals or when the timestamps do not advance.
  std::optional<double> fps() const;

 private:
  std::uint64_t frames_ = 0;
  std::int64_t first_ns_ = 0, last_ns_ = 0;
};

struct SlowDelivery {
  std::string node;
  double delivered_fps = 0, granted_fps = 0, span_seconds = 0;
  std::uint64_t frames = 0, dropped_frames = 0, error_buffers = 0;
};
// The warning for a take that delivered less than (1 - kSlowRateMargin) x the granted rate, with
// both rates, what was counted lost and the usual causes; empty otherwise.
std::string slow_delivery_warning(const SlowDelivery& take);

}  // namespace haptex::capture
