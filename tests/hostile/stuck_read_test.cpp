// Review 14, F9: libhdf5 1.10 loops forever, at full CPU, reading a variable-length value whose global
// heap collection holds a zeroed object header (an object of index 0 and size 0 never moves its
// parser on). No error comes back, so haptex bounds such reads by processor time
// (core/bounded_call.hpp): the command ends with exit 2 naming the file and the value, and nothing
// written, instead of spinning until killed.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>
#include <vector>

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

// capture extract refuses `damaged` as a read that does not end, within the probe's bound.
void expect_refused_by_the_bound(const TempDir& dir, const std::string& damaged) {
  const auto start = std::chrono::steady_clock::now();
  const CommandResult r = run_haptex({"capture", "extract", damaged, "-o", dir.file("g.h5"), "--no-sheets"});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  expect_refusal(r, {damaged, "does not end", "damaged"});
  EXPECT_LT(seconds, 4 * kStuckCallSeconds) << "ended by the bound, not by the test's time limit";
  EXPECT_EQ(partial_files(dir.path().string()), std::vector<std::string>{});
}

// Review 28, F4: the probe's processor time followed the file's size, so the same damage padded with a
// sparse hole to 3 GB looped 86 s before it was refused. A hole counts for nothing.
TEST(StuckRead, AHoleInTheFileBuysTheProbeNoTime) {
  const TempDir dir;
  const std::string damaged = press_file_with_a_looping_heap(dir);
  ASSERT_FALSE(damaged.empty());
  fs::resize_file(damaged, std::uintmax_t(3) << 30);  // sparse: a few hundred KB on disk
  expect_refused_by_the_bound(dir, damaged);
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
  expect_refused_by_the_bound(dir, damaged);
}

// The haptex-h5-probe processes whose parent is `parent`.
std::vector<pid_t> probes_of(pid_t parent) {
  std::vector<pid_t> found;
  for (const fs::directory_entry& entry : fs::directory_iterator("/proc")) {
    std::ifstream stat(entry.path() / "stat");
    std::string line;
    if (!std::getline(stat, line) || line.find("(haptex-h5-probe)") == std::string::npos) continue;
    std::istringstream after(line.substr(line.rfind(')') + 2));
    char state = 0;
    pid_t ppid = 0;
    after >> state >> ppid;
    if (ppid == parent && state != 'Z') found.push_back(pid_t(std::stoi(entry.path().filename().string())));
  }
  return found;
}

bool running(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  return std::getline(stat, line) && line.substr(line.rfind(')') + 2, 1) != "Z";
}

// Review 30, F3: haptex stopped by a signal sent to it alone (kill PID, a batch system's TERM) left its
// probe running, orphaned, until the probe's processor limit ended it. The probe ends with haptex.
TEST(StuckRead, TheProbeEndsWithHaptex) {
  const TempDir dir;
  const std::string damaged = press_file_with_a_looping_heap(dir);
  ASSERT_FALSE(damaged.empty());
  const std::string output = dir.file("g.h5");
  const pid_t haptex = fork();
  ASSERT_GE(haptex, 0);
  if (haptex == 0) {
    std::freopen("/dev/null", "w", stdout);
    std::freopen("/dev/null", "w", stderr);
    execl(HAPTEX_BINARY, HAPTEX_BINARY, "capture", "extract", damaged.c_str(), "-o", output.c_str(), "--no-sheets",
          static_cast<char*>(nullptr));
    _exit(127);
  }
  std::vector<pid_t> probes;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while ((probes = probes_of(haptex)).empty() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ASSERT_EQ(probes.size(), 1u) << "haptex runs one probe on the looping heap";
  kill(haptex, SIGTERM);
  int status = 0;
  waitpid(haptex, &status, 0);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM) << "haptex ends by the signal, once it has cleaned up: " << status;
  const auto gone_by = std::chrono::steady_clock::now() + std::chrono::seconds(3);
  while (running(probes[0]) && std::chrono::steady_clock::now() < gone_by) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_FALSE(running(probes[0])) << "the probe outlived haptex";
  EXPECT_FALSE(fs::exists(output));
}

}  // namespace
}  // namespace haptex::test
