#pragma once
// One frame as the driver delivered it: the payload bytes (MJPG exactly as the sensor sent it,
// or raw YUYV) and the metadata V4L2 attached to its buffer.
#include <cstdint>
#include <vector>

namespace haptex::capture {

struct Frame {
  std::uint32_t sequence = 0;      // the driver's frame counter; gaps are frames lost before us
  std::int64_t timestamp_ns = 0;   // CLOCK_MONOTONIC time the driver stamped
  std::uint32_t flags = 0;         // V4L2_BUF_FLAG_*
  std::vector<std::uint8_t> bytes; // bytesused bytes of the buffer
};

}  // namespace haptex::capture
