#pragma once
// The one main of every bench program, after its own export flags: Google Benchmark's, with the heap
// set as the haptex binary sets it (core/freed_memory.hpp), so the library is timed as haptex runs it.
#include <benchmark/benchmark.h>

#include "core/freed_memory.hpp"

namespace haptex::bench {

inline int run_benchmarks(int argc, char** argv) {
  keep_freed_memory();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

}  // namespace haptex::bench
