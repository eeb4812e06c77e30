#include "core/freed_memory.hpp"

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <fstream>
#include <memory>
#include <string>

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
    volatile char* pages = buffer.get();  // the writes must happen: the compiler may not drop them
    for (std::size_t i = 0; i < size; i += 4096) pages[i] = char(i);
  }
  return minor_faults() - before;
}

// With transparent huge pages always on, 24 MB take a dozen faults either way: nothing to tell apart.
bool huge_pages_always() {
  std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string setting;
  std::getline(in, setting);
  return setting.find("[always]") != std::string::npos;
}

// The second file's buffer reuses the first's pages: no fresh page per 4 KB (6144 of them).
TEST(FreedMemory, ABufferFreedIsReusedWithoutPageFaults) {
  if (!haptex::keep_freed_memory()) GTEST_SKIP() << "not 64-bit glibc: keep_freed_memory changes nothing here";
  if (huge_pages_always()) GTEST_SKIP() << "transparent huge pages are always on";
  faults_of_a_buffer();
  EXPECT_LT(faults_of_a_buffer(), 100) << "the freed 24 MB went back to the kernel: every page faulted again";
}

}  // namespace
