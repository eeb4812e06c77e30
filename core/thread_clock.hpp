#pragma once
// Compute time of the calling thread, for speed figures measured while other threads work (the
// evaluation runs materials in parallel, and wall time would count the others).
#include <time.h>

namespace haptex {

inline double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

}  // namespace haptex
