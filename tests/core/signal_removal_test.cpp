// Ctrl-C, TERM or HUP removes the run's unfinished outputs even while another thread of the run
// still writes into them (issue 32, review 5 finding 5: a library opening a temporary by name right
// after it was removed made it anew; a file made in a folder while it was removed kept the folder).
// A child process takes the signal, as a run would.
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <atomic>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <thread>

#include "core/durable_file.hpp"
#include "core/partial_directory.hpp"
#include "core/temporary_name.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex {
namespace {
namespace fs = std::filesystem;

// Runs `write` on a thread of a child process that, 20 ms later, sends itself SIGINT; returns the
// child's wait status.
int interrupted_while(const std::function<void()>& make_output, const std::function<void()>& write) {
  const pid_t child = ::fork();
  if (child == 0) {
    remove_temporaries_on_signals();
    make_output();
    std::thread([&] {
      for (;;) write();
    }).detach();
    ::usleep(20000);
    ::kill(::getpid(), SIGINT);
    ::sleep(10);  // the signal ends it here
    ::_exit(0);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  return status;
}

TEST(SignalRemoval, AFolderBeingFilledIsRemovedWhole) {
  for (int run = 0; run < 5; ++run) {
    const test::TempDir dir;
    const std::string report = dir.file("report");
    std::unique_ptr<PartialDirectory> folder;
    std::atomic<int> made{0};
    const int status = interrupted_while([&] { folder = std::make_unique<PartialDirectory>(report, FolderOptions{}); },
                                         [&] {
                                           const std::string name = folder->path() + "/figure_" + std::to_string(made++);
                                           std::ofstream(name) << "plot";
                                           std::error_code failed;  // once the folder is gone: as a run's error, which then waits
                                           fs::create_directory(name + ".d", failed);
                                         });
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGINT) << "status " << status;
    EXPECT_TRUE(temporaries_of(report).empty()) << "run " << run;
    EXPECT_FALSE(fs::exists(report));
  }
}

TEST(SignalRemoval, AFileOpenedByNameIsNeverMadeAnew) {
  for (int run = 0; run < 5; ++run) {
    const test::TempDir dir;
    const std::string out = dir.file("r.h5");
    std::unique_ptr<PartialFile> partial;
    const int status = interrupted_while([&] { partial = std::make_unique<PartialFile>(out, false); },
                                         [&] {
                                           partial->open_by_name([](const std::string& path) {  // as HDF5 and libsndfile open it
                                             const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
                                             if (fd >= 0) ::close(fd);
                                             return fd;
                                           });
                                         });
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGINT) << "status " << status;
    EXPECT_TRUE(temporaries_of(out).empty()) << "run " << run;
  }
}

}  // namespace
}  // namespace haptex
