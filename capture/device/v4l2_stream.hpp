#pragma once
// Memory-mapped V4L2 streaming: 4 to 8 driver buffers, waited for with poll on a non-blocking
// node. Each frame is copied out of its buffer and the buffer is queued again at once, so the
// driver always has free buffers and never drops a frame because we held on to one.
#include <cstdint>
#include <vector>

#include "capture/device/drop_counter.hpp"
#include "capture/device/format_negotiation.hpp"
#include "capture/device/frame.hpp"
#include "capture/device/v4l2_device.hpp"

namespace haptex::capture {

struct StreamStats {
  std::uint64_t frames = 0;          // delivered to the caller
  std::uint64_t error_buffers = 0;   // flagged V4L2_BUF_FLAG_ERROR, empty, or DQBUF EIO: requeued, not delivered
  std::uint64_t poll_timeouts = 0;   // polls that saw no frame within the timeout
};

// `ended`: the device said it will send no more (a buffer flagged V4L2_BUF_FLAG_LAST, then EPIPE), as
// a finite source does; a camera never does. A replayed file ends so (capture/replay/).
// no_frame: a buffer came back holding no usable frame (flagged as an error, or empty); its time is in
// the Frame's timestamp_ns (0 when the driver gave none), so the caller can count the time without a
// frame and look at its stop flag (review 6: a sensor sending only error buffers held the take forever).
enum class StreamStatus { frame, no_frame, timeout, disconnected, ended };

class V4l2Stream {
 public:
  static constexpr unsigned kMinBuffers = 4, kMaxBuffers = 8;

  // Requests `buffers` (clamped to 4..8) mmap buffers and maps them. Throws haptex::Error (failed)
  // when the driver grants fewer than 4.
  V4l2Stream(const V4l2Device& device, const StreamFormat& format, unsigned buffers = 6);
  ~V4l2Stream();  // stops streaming, unmaps and frees the buffers
  V4l2Stream(const V4l2Stream&) = delete;
  V4l2Stream& operator=(const V4l2Stream&) = delete;

  void start();  // queues every buffer, STREAMON
  void stop();   // STREAMOFF; safe to call twice and after a disconnect

  // Waits up to poll_timeout_ms() for the next good frame. `disconnected` (ENODEV, or a queue the
  // driver has put in its error state) and `ended` end the take; frames delivered before stay the caller's.
  StreamStatus next(Frame& out);
  // Three frame periods, at least 50 ms: long enough for jitter, short enough to notice a stall.
  int poll_timeout_ms() const;

  unsigned buffer_count() const { return static_cast<unsigned>(buffers_.size()); }
  const StreamStats& stats() const { return stats_; }
  const DropCounter& drops() const { return drops_; }
  const StreamFormat& format() const { return format_; }

 private:
  struct Mapped {
    void* start = nullptr;
    std::size_t length = 0;
  };
  enum class Dequeue { frame, skipped, empty, disconnected, ended };
  Dequeue dequeue(Frame& out);
  void queue(std::uint32_t index);
  void release_buffers() noexcept;

  const V4l2Device& device_;
  StreamFormat format_;
  std::vector<Mapped> buffers_;
  DropCounter drops_;
  StreamStats stats_;
  bool streaming_ = false;
  bool ended_ = false;  // the driver flagged a buffer LAST
  int consecutive_queue_errors_ = 0;
};

}  // namespace haptex::capture
