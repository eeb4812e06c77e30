#include "core/bounded_call.hpp"

#include <pthread.h>
#include <time.h>

#include <chrono>
#include <cstdint>
#include <mutex>
#include <thread>

#include "core/text/format.hpp"

namespace haptex {
namespace {

struct Watch {
  std::mutex lock;
  std::function<void(const Error&)> handler;
  bool started = false;
  // The call being watched: 0 when none.
  std::uint64_t call = 0, calls = 0;
  clockid_t clock{};
  std::string file, where;
};

Watch& watch() {
  static Watch* w = new Watch;  // never destroyed: the watchdog may look at it while the process exits
  return *w;
}

double seconds_of(clockid_t clock) {
  timespec t{};
  if (clock_gettime(clock, &t) != 0) return 0;  // the thread has ended: its call has too
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// Looks at the watched call twice a second; the processor time its thread has used since the first
// look is what counts (a call seen late is given its full bound from then on).
[[noreturn]] void watchdog() {
  Watch& w = watch();
  std::uint64_t seen = 0;
  double since = 0;
  for (;;) {
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    std::unique_lock<std::mutex> held(w.lock);
    if (w.call == 0) continue;
    if (w.call != seen) {
      seen = w.call;
      since = seconds_of(w.clock);
      continue;
    }
    if (seconds_of(w.clock) - since < kStuckCallSeconds) continue;
    const Error stuck = input_error(
        w.file, w.where,
        text::format("reading it does not end (%g s of processor time without an answer; HDF5 loops so on a "
                     "damaged variable-length value, whose global heap was overwritten)",
                     kStuckCallSeconds),
        "The file is damaged: copy it again, or make it again with the haptex command that wrote it");
    const auto handler = w.handler;
    held.unlock();
    handler(stuck);
    for (;;) std::this_thread::sleep_for(std::chrono::hours(1));  // the handler ends the process
  }
}

}  // namespace

BoundedCall::BoundedCall(const std::string& file, const std::string& where) {
  Watch& w = watch();
  const std::lock_guard<std::mutex> held(w.lock);
  if (!w.handler) return;
  if (!w.started) {
    std::thread(watchdog).detach();
    w.started = true;
  }
  if (pthread_getcpuclockid(pthread_self(), &w.clock) != 0) return;
  w.call = ++w.calls;
  w.file = file;
  w.where = where;
  armed_ = true;
}

BoundedCall::~BoundedCall() {
  if (!armed_) return;
  Watch& w = watch();
  const std::lock_guard<std::mutex> held(w.lock);
  w.call = 0;
}

void on_stuck_call(std::function<void(const Error&)> handler) {
  Watch& w = watch();
  const std::lock_guard<std::mutex> held(w.lock);
  w.handler = std::move(handler);
}

}  // namespace haptex
