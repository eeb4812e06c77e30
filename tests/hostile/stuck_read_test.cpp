// Review 14, F9: libhdf5 1.10 loops forever, at full CPU, reading a variable-length value whose global
// heap collection holds a zeroed object header (an object of index 0 and size 0 never moves its
// parser on). No error comes back, so haptex bounds such reads by processor time
// (core/bounded_call.hpp): the command ends with exit 2 naming the file and the value, and nothing
// written, instead of spinning until killed.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/bounded_call.hpp"
#include "tests/hostile/hostile_support.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {
namespace fs = std::filesystem;

// A press file whose frames' heap collection starts with a zeroed object header: its 16-byte
// collection header ("GCOL", version, reserved, size) is kept, the first object's header is zeroed.
std::string press_file_with_a_looping_heap(const TempDir& dir) {
  const std::string session = dir.file("s");
  EXPECT_EQ(run_haptex({"capture", "record", "--device", "fake:size=160x120,lockstep", "--material", "Cork", "--presses", "1", "-o",
                        session, "-q"}).exit_code, 0);
  std::string bytes = file_bytes(session + "/press_0.h5");
  const std::size_t heap = bytes.find("GCOL", 2049);
  EXPECT_NE(heap, std::string::npos);
  if (heap == std::string::npos) return "";
  bytes.replace(heap + 16, 16, std::string(16, '\0'));
  const std::string damaged = dir.file("looping heap.h5");
  std::ofstream(damaged, std::ios::binary) << bytes;
  return damaged;
}

TEST(StuckRead, AHeapThatLoopsHDF5IsBadInputNamingTheFrame) {
  const TempDir dir;
  const std::string damaged = press_file_with_a_looping_heap(dir);
  ASSERT_FALSE(damaged.empty());
  const auto start = std::chrono::steady_clock::now();
  const CommandResult r = run_haptex({"capture", "extract", damaged, "-o", dir.file("g.h5"), "--no-sheets", "--explain"});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  expect_refusal(r, {damaged, "/frames, element 0", "does not end", "damaged"});
  EXPECT_LT(seconds, 4 * kStuckCallSeconds) << "ended by the bound, not by the test's time limit";
  EXPECT_FALSE(fs::exists(dir.file("g.h5")));
  EXPECT_FALSE(fs::exists(dir.file("g_explain")));
  EXPECT_EQ(partial_files(dir.path().string()), std::vector<std::string>{}) << "the run's temporaries are removed";
}

// Review 28, F4: the probe's processor time followed the file's size, so the same damage padded with a
// sparse hole to 3 GB looped 86 s before it was refused. A hole counts for nothing.
TEST(StuckRead, AHoleInTheFileBuysTheProbeNoTime) {
  const TempDir dir;
  const std::string damaged = press_file_with_a_looping_heap(dir);
  ASSERT_FALSE(damaged.empty());
  fs::resize_file(damaged, std::uintmax_t(3) << 30);  // sparse: a few hundred KB on disk
  const auto start = std::chrono::steady_clock::now();
  const CommandResult r = run_haptex({"capture", "extract", damaged, "-o", dir.file("g.h5"), "--no-sheets"});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  expect_refusal(r, {damaged, "does not end", "damaged"});
  EXPECT_LT(seconds, 4 * kStuckCallSeconds) << "ended by the bound, not by the test's time limit";
  EXPECT_EQ(partial_files(dir.path().string()), std::vector<std::string>{});
}

// Review 29, F2: zeros really on disk past the file's end (a copy or download of the padded file, or
// fallocate) bought the probe 73 s. What lies past the superblock's end of address counts for nothing.
TEST(StuckRead, ZerosOnDiskPastTheFilesEndBuyTheProbeNoTime) {
  const TempDir dir;
  const std::string damaged = press_file_with_a_looping_heap(dir);
  ASSERT_FALSE(damaged.empty());
  const off_t size = off_t(fs::file_size(damaged)), padding = off_t(2) << 30;  // once 40 s more
  const int fd = ::open(damaged.c_str(), O_WRONLY | O_CLOEXEC);
  ASSERT_GE(fd, 0);
  const bool allocated = ::fallocate(fd, 0, size, padding) == 0;
  ::close(fd);
  if (!allocated) GTEST_SKIP() << "this file system cannot allocate 2 GB here: " << std::strerror(errno);
  struct stat s {};
  ASSERT_EQ(::stat(damaged.c_str(), &s), 0);
  ASSERT_GE(off_t(s.st_blocks) * 512, padding) << "the padding is on disk, not a hole";
  const auto start = std::chrono::steady_clock::now();
  const CommandResult r = run_haptex({"capture", "extract", damaged, "-o", dir.file("g.h5"), "--no-sheets"});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  expect_refusal(r, {damaged, "does not end", "damaged"});
  EXPECT_LT(seconds, 4 * kStuckCallSeconds) << "ended by the bound, not by the test's time limit";
  EXPECT_EQ(partial_files(dir.path().string()), std::vector<std::string>{});
}

}  // namespace
}  // namespace haptex::test
