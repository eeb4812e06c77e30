#include "capture/device/v4l2_stream.hpp"

#include <linux/videodev2.h>
#include <sys/mman.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>

#include "core/error.hpp"

namespace haptex::capture {
namespace {

// A driver whose queue is in its error state answers every poll with POLLERR and every DQBUF with
// EIO; a few in a row without a good frame means the device is gone.
constexpr int kQueueErrorsBeforeDisconnect = 3;

v4l2_buffer mmap_buffer(std::uint32_t index = 0) {
  v4l2_buffer b{};
  b.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  b.memory = V4L2_MEMORY_MMAP;
  b.index = index;
  return b;
}

}  // namespace

V4l2Stream::V4l2Stream(const V4l2Device& device, const StreamFormat& format, unsigned buffers)
    : device_(device), format_(format), drops_(format.period_ns()) {
  v4l2_requestbuffers request{};
  request.count = std::clamp(buffers, kMinBuffers, kMaxBuffers);
  request.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  request.memory = V4L2_MEMORY_MMAP;
  device_.ioctl_or_throw(VIDIOC_REQBUFS, &request, "VIDIOC_REQBUFS (mmap buffers)");
  if (request.count < kMinBuffers) {
    release_buffers();
    throw failure(device_.path() + ": the driver granted " + std::to_string(request.count) +
                  " capture buffers; haptex needs at least 4 to keep up. Close other programs using the camera");
  }
  try {
    for (std::uint32_t i = 0; i < request.count; ++i) {
      v4l2_buffer b = mmap_buffer(i);
      device_.ioctl_or_throw(VIDIOC_QUERYBUF, &b, "VIDIOC_QUERYBUF");
      void* start = device_.kernel().mmap(nullptr, b.length, PROT_READ | PROT_WRITE, MAP_SHARED, device_.fd(), b.m.offset);
      if (start == MAP_FAILED) throw failure(device_.path() + ": mmap of capture buffer failed: " + std::strerror(errno));
      buffers_.push_back({start, b.length});
    }
  } catch (...) {
    release_buffers();
    throw;
  }
}

V4l2Stream::~V4l2Stream() {
  stop();
  release_buffers();
}

void V4l2Stream::release_buffers() noexcept {
  for (const auto& b : buffers_) device_.kernel().munmap(b.start, b.length);
  buffers_.clear();
  v4l2_requestbuffers request{};
  request.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  request.memory = V4L2_MEMORY_MMAP;
  device_.try_ioctl(VIDIOC_REQBUFS, &request);  // count 0 frees them; fails harmlessly after a disconnect
}

void V4l2Stream::queue(std::uint32_t index) {
  v4l2_buffer b = mmap_buffer(index);
  const int error = device_.try_ioctl(VIDIOC_QBUF, &b);
  // After a disconnect QBUF fails too; the next poll or DQBUF reports it.
  if (error != 0 && error != ENODEV && error != EIO)
    throw failure(device_.path() + ": VIDIOC_QBUF failed: " + std::strerror(error));
}

void V4l2Stream::start() {
  for (std::uint32_t i = 0; i < buffers_.size(); ++i) queue(i);
  int type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  device_.ioctl_or_throw(VIDIOC_STREAMON, &type, "VIDIOC_STREAMON");
  streaming_ = true;
  ended_ = false;
}

void V4l2Stream::stop() {
  if (!streaming_) return;
  streaming_ = false;
  int type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  device_.try_ioctl(VIDIOC_STREAMOFF, &type);
}

int V4l2Stream::poll_timeout_ms() const {
  return std::max(50, static_cast<int>(std::ceil(3 * format_.period_ns() / 1e6)));
}

V4l2Stream::Dequeue V4l2Stream::dequeue(Frame& out) {
  v4l2_buffer b = mmap_buffer();
  const int error = device_.try_ioctl(VIDIOC_DQBUF, &b);
  if (error == EAGAIN) return Dequeue::empty;
  if (error == ENODEV) return Dequeue::disconnected;
  if (error == EPIPE) return Dequeue::ended;  // the LAST buffer was dequeued before
  if (error == EIO) {
    ++stats_.error_buffers;
    out.bytes.clear();
    out.timestamp_ns = 0;
    return ++consecutive_queue_errors_ >= kQueueErrorsBeforeDisconnect ? Dequeue::disconnected : Dequeue::skipped;
  }
  if (error != 0) throw failure(device_.path() + ": VIDIOC_DQBUF failed: " + std::strerror(error));
  consecutive_queue_errors_ = 0;
  if (b.flags & V4L2_BUF_FLAG_LAST) ended_ = true;
  // An empty LAST buffer only marks the end: it is no frame, no error and no loss.
  if (ended_ && b.bytesused == 0) return Dequeue::ended;
  const std::int64_t timestamp_ns = std::int64_t(b.timestamp.tv_sec) * 1000000000 + std::int64_t(b.timestamp.tv_usec) * 1000;
  const bool bad = (b.flags & V4L2_BUF_FLAG_ERROR) || b.bytesused == 0 || b.index >= buffers_.size();
  if (b.index < buffers_.size() && !bad) {
    const auto* bytes = static_cast<const std::uint8_t*>(buffers_[b.index].start);
    out.bytes.assign(bytes, bytes + std::min<std::size_t>(b.bytesused, buffers_[b.index].length));
    out.sequence = b.sequence;
    out.timestamp_ns = timestamp_ns;
    out.flags = b.flags;
  }
  // The loss count uses every buffer the driver returned, so a flagged one is not also counted as lost.
  if (timestamp_ns != 0) drops_.observe(b.sequence, timestamp_ns);
  if (b.index < buffers_.size()) queue(b.index);
  if (bad) {
    ++stats_.error_buffers;
    out.bytes.clear();
    out.timestamp_ns = timestamp_ns;
    return Dequeue::skipped;
  }
  ++stats_.frames;
  return Dequeue::frame;
}

StreamStatus V4l2Stream::next(Frame& out) {
  for (;;) {
    if (ended_) return StreamStatus::ended;  // a LAST buffer that carried the final frame
    switch (dequeue(out)) {
      case Dequeue::frame: return StreamStatus::frame;
      case Dequeue::skipped: return StreamStatus::no_frame;
      case Dequeue::disconnected: return StreamStatus::disconnected;
      case Dequeue::ended: return StreamStatus::ended;
      case Dequeue::empty: break;
    }
    pollfd p{device_.fd(), POLLIN, 0};
    const int ready = device_.kernel().poll(&p, 1, poll_timeout_ms());
    if (ready < 0 && errno == EINTR) return StreamStatus::timeout;  // a signal: let the caller look at its stop flag
    if (ready < 0) throw failure(device_.path() + ": poll failed: " + std::strerror(errno));
    if (ready == 0) {
      ++stats_.poll_timeouts;
      return StreamStatus::timeout;
    }
    if ((p.revents & (POLLERR | POLLHUP)) && !(p.revents & POLLIN)) {
      const Dequeue d = dequeue(out);  // ENODEV says so directly; otherwise count towards the error state
      if (d == Dequeue::frame) return StreamStatus::frame;
      if (d == Dequeue::skipped) return StreamStatus::no_frame;
      if (d == Dequeue::disconnected) return StreamStatus::disconnected;
      if (d == Dequeue::ended) return StreamStatus::ended;
      if (d == Dequeue::empty && ++consecutive_queue_errors_ >= kQueueErrorsBeforeDisconnect)
        return StreamStatus::disconnected;
    }
  }
}

}  // namespace haptex::capture
