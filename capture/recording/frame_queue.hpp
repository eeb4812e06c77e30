#pragma once
// The hand-over from the capture thread to the processing thread. Deep, so the capture thread of a
// live sensor does not wait (the driver would run out of buffers and drop frames), but bounded: a
// source that outruns the scorer (a fake or replayed file in lockstep, which makes frames as fast as
// they are taken) waits for it instead of filling memory (review 6: 8.7 GB in a minute) and making
// Ctrl-C wait for every frame queued. Its deepest point is reported, so a recorder that falls behind
// shows it.
#include <algorithm>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <optional>

namespace haptex::capture {

template <typename T>
class FrameQueue {
 public:
  explicit FrameQueue(std::size_t capacity) : capacity_(std::max<std::size_t>(capacity, 1)) {}

  // Waits while the queue is full (and open).
  void push(T item) {
    {
      std::unique_lock lock(mutex_);
      room_.wait(lock, [&] { return items_.size() < capacity_ || closed_; });
      items_.push_back(std::move(item));
      max_depth_ = std::max(max_depth_, items_.size());
    }
    ready_.notify_one();
  }
  // Waits for an item; nullopt once closed and empty.
  std::optional<T> pop() {
    std::unique_lock lock(mutex_);
    ready_.wait(lock, [&] { return !items_.empty() || closed_; });
    if (items_.empty()) return std::nullopt;
    T item = std::move(items_.front());
    items_.pop_front();
    room_.notify_one();
    return item;
  }
  void close() {
    {
      std::lock_guard lock(mutex_);
      closed_ = true;
    }
    ready_.notify_all();
    room_.notify_all();
  }
  std::size_t max_depth() const {
    std::lock_guard lock(mutex_);
    return max_depth_;
  }

 private:
  mutable std::mutex mutex_;
  std::condition_variable ready_, room_;
  const std::size_t capacity_;
  std::deque<T> items_;
  std::size_t max_depth_ = 0;
  bool closed_ = false;
};

}  // namespace haptex::capture
