#pragma once
// The hand-over from the capture thread to the processing thread. Unbounded on purpose: the capture
// thread must never wait, or the driver runs out of buffers and drops frames. Its deepest point is
// reported, so a recorder that falls behind shows it.
#include <condition_variable>
#include <deque>
#include <mutex>
#include <optional>

namespace haptex::capture {

template <typename T>
class FrameQueue {
 public:
  void push(T item) {
    {
      std::lock_guard lock(mutex_);
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
    return item;
  }
  void close() {
    {
      std::lock_guard lock(mutex_);
      closed_ = true;
    }
    ready_.notify_all();
  }
  std::size_t max_depth() const {
    std::lock_guard lock(mutex_);
    return max_depth_;
  }

 private:
  mutable std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<T> items_;
  std::size_t max_depth_ = 0;
  bool closed_ = false;
};

}  // namespace haptex::capture
