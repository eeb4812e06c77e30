#include "capture/device/drop_counter.hpp"

#include <algorithm>
#include <cmath>

namespace haptex::capture {

std::uint64_t DropCounter::observe(std::uint32_t sequence, std::int64_t timestamp_ns, std::uint64_t flagged) {
  if (first_) {
    first_ = false;
    last_sequence_ = sequence;
    last_timestamp_ns_ = timestamp_ns;
    return 0;
  }
  // Unsigned subtraction: the 32-bit counter may wrap around during a long take.
  const std::uint32_t step = sequence - last_sequence_;
  const std::uint64_t gap = step > 0 ? step - 1 : 0;
  const std::uint64_t by_sequence = gap - std::min(gap, flagged);
  std::uint64_t by_time = 0;
  const double dt = double(timestamp_ns - last_timestamp_ns_);
  if (dt > 1.5 * period_ns_) by_time = std::uint64_t(std::llround(dt / period_ns_)) - 1;
  by_time -= std::min(by_time, flagged);
  last_sequence_ = sequence;
  last_timestamp_ns_ = timestamp_ns;
  const std::uint64_t lost = std::max(by_sequence, by_time);
  sequence_gaps_ += by_sequence;
  timestamp_gaps_ += lost - by_sequence;
  dropped_ += lost;
  return lost;
}

}  // namespace haptex::capture
