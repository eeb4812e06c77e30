#pragma once
// Actions from a live source: lines of `force speed` (or `t,force,speed`, or with commas) on a file
// descriptor, standard input for `haptex play --actions -`, so that any device driver can pipe into
// it. Each line is the action from the moment it arrives (a t column must be a number but is not used
// for timing: a live stream's time is when it comes). A first line naming columns is a header.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace haptex::play {

using Clock = std::chrono::steady_clock;

struct ActionLine {
  Clock::time_point arrived;
  float force = 0, speed = 0;  // N, mm/s
};

// One line's action, or nullopt for a header (`first`: the first line that is not blank; a header
// names columns with letters, digits and '_'); throws haptex::Error (bad_input) naming `source` and
// line `number`: not two or three fields (commas separate them exactly, else spaces), a value that is
// not finite or beyond a 32-bit float, a negative force or speed. A `t` field must be a number; it is
// not used for timing.
std::optional<ActionLine> parse_action_line(const std::string& line, const std::string& source, std::size_t number, bool first);

class ActionStream {
 public:
  // Reads fd on a thread of its own until it ends (or the stream is destroyed). `source` names it in errors.
  ActionStream(int fd, std::string source);
  ~ActionStream();
  ActionStream(const ActionStream&) = delete;
  ActionStream& operator=(const ActionStream&) = delete;

  const std::string& source() const { return source_; }
  // Waits for the first line (or the end); false when the stream ended without one.
  bool wait_for_first(const std::atomic<bool>& stop);
  // Moves the lines that arrived up to `until` into `out` (cleared first). False once the stream has
  // ended (its end, or a bad line: then error()) and all is taken.
  bool take(Clock::time_point until, std::deque<ActionLine>& out);
  // What a bad line threw (haptex::Error, bad_input, naming the source and the line), or null. The
  // lines before it are played; the player throws it when it has played them.
  std::exception_ptr error();

 private:
  void read_lines();
  int fd_;
  std::string source_;
  std::mutex mutex_;
  std::condition_variable arrived_;
  std::deque<ActionLine> lines_;
  std::exception_ptr error_;  // what a bad line threw
  bool ended_ = false;
  std::atomic<bool> closing_{false};
  std::thread reader_;
};

}  // namespace haptex::play
