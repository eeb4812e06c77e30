#pragma once
// Runs independent work items on all cores. Results must not depend on which thread runs what:
// each item derives its own random seed from its index.
#include <cstddef>
#include <functional>

namespace haptex {

// The cores this process may run on (its CPU affinity: taskset, a container's limits); at least 1.
unsigned available_cores();

// Calls work(i) for i in [0, count) on up to `threads` threads (0: one per core). The first
// exception thrown by any item is rethrown here after all threads have stopped.
void parallel_for(std::size_t count, const std::function<void(std::size_t)>& work, unsigned threads = 0);

}  // namespace haptex
