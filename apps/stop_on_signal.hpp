#pragma once
// For commands that end by themselves on a signal (Command::ends_on_signals_itself): capture record
// closes the press in progress, play stops the sound and keeps its recording.
#include <atomic>
#include <csignal>

namespace haptex::apps {

// While one lives, SIGINT, SIGTERM and SIGHUP (the terminal or the ssh session closed) set
// stop_requested(); a second Ctrl-C kills as usual. A signal ignored when haptex started (nohup's HUP,
// a background job's INT) stays ignored.
class StopOnSignal {
 public:
  StopOnSignal();
  ~StopOnSignal();
  StopOnSignal(const StopOnSignal&) = delete;
  StopOnSignal& operator=(const StopOnSignal&) = delete;
  static const std::atomic<bool>& stop_requested();

 private:
  struct sigaction old_int_ {}, old_term_ {}, old_hup_ {};
};

}  // namespace haptex::apps
