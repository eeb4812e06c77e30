#include "core/parallel.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

namespace haptex {
namespace {

TEST(ParallelFor, RunsEveryItemOnce) {
  std::vector<std::atomic<int>> runs(1000);
  parallel_for(runs.size(), [&](std::size_t i) { ++runs[i]; }, 4);
  for (const auto& r : runs) EXPECT_EQ(r.load(), 1);
}

TEST(ParallelFor, RethrowsTheFirstErrorAfterStopping) {
  std::atomic<int> done{0};
  EXPECT_THROW(parallel_for(100, [&](std::size_t i) {
                 if (i == 3) throw std::runtime_error("item 3 failed");
                 ++done;
               }, 2),
               std::runtime_error);
  EXPECT_LT(done.load(), 100);
}

TEST(ParallelFor, NothingToDo) {
  EXPECT_NO_THROW(parallel_for(0, [](std::size_t) { throw std::runtime_error("never"); }));
}

}  // namespace
}  // namespace haptex
