#include "apps/stop_on_signal.hpp"

namespace haptex::apps {
namespace {

std::atomic<bool> g_stop{false};

extern "C" void request_stop(int) { g_stop = true; }

void take(int signal, const struct sigaction& action, struct sigaction& old) {
  sigaction(signal, nullptr, &old);
  if (old.sa_handler != SIG_IGN) sigaction(signal, &action, nullptr);
}

}  // namespace

StopOnSignal::StopOnSignal() {
  g_stop = false;
  struct sigaction action {};
  action.sa_handler = request_stop;
  sigemptyset(&action.sa_mask);
  // TERM and HUP may come twice (timeout forwards them, a closing terminal repeats them): they keep
  // asking to stop. Only a second Ctrl-C kills, as a user expects.
  take(SIGTERM, action, old_term_);
  take(SIGHUP, action, old_hup_);
  action.sa_flags = SA_RESETHAND;
  take(SIGINT, action, old_int_);
}

StopOnSignal::~StopOnSignal() {
  sigaction(SIGINT, &old_int_, nullptr);
  sigaction(SIGTERM, &old_term_, nullptr);
  sigaction(SIGHUP, &old_hup_, nullptr);
}

const std::atomic<bool>& StopOnSignal::stop_requested() { return g_stop; }

}  // namespace haptex::apps
