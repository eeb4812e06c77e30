#include "core/freed_memory.hpp"

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <cstdlib>
#include <memory>

namespace {

long minor_faults() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_minflt;
}

// Allocates, touches and frees 24 MB (a HaTT recording's XML buffer); returns the page faults it took.
long faults_of_a_buffer() {
  const std::size_t size = std::size_t(24) << 20;
  const long before = minor_faults();
  {
    std::unique_ptr<char[]> buffer(new char[size]);
    for (std::size_t i = 0; i < size; i += 4096) buffer[i] = char(i);
    volatile char keep = buffer[size / 2];
    (void)keep;
  }
  return minor_faults() - before;
}

#if defined(__GLIBC__)
// The second file's buffer reuses the first's pages: no fresh page per 4 KB (6144 of them).
TEST(FreedMemory, ABufferFreedIsReusedWithoutPageFaults) {
  haptex::keep_freed_memory();
  faults_of_a_buffer();
  EXPECT_LT(faults_of_a_buffer(), 100) << "the freed 24 MB went back to the kernel: every page faulted again";
}
#endif

}  // namespace
