// haptex-h5-probe [--values] FILE: reads the structure of an HDF5 file (with --values: its
// variable-length byte values) in a process of its own, so that damage crashing libhdf5 ends this
// program, not haptex (core/h5/structure_probe.hpp). Writes the place it reads next, NUL-ended, to
// standard output.
// Exit code 0 when all was read, 1 when HDF5 refused a read (its place, finding and fix follow), 3 when
// HDF5 could not open the file, 64 on a wrong command line; a signal when it crashed, SIGXCPU once it
// used its processor time (HDF5 loops on some damage), SIGALRM when it waited four times as long. Only
// 0 says the file can be read. It starts itself again under AddressSanitizer's runtime when it can; a
// caller that gets no output at all runs it again with HAPTEX_PROBE_AS_IS=1, without.
#include <dlfcn.h>
#include <limits.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <string_view>
#include <vector>

#include "core/bounded_call.hpp"
#include "core/h5/structure_probe.hpp"

namespace {

const char* probed_name = nullptr;  // the FILE argument, as HDF5 is given it

// The processor time the probe may use: a reader's bound on one stuck call (kStuckCallSeconds), plus
// a second per 50 MB of the file HDF5 can read, far slower than HDF5 reads any file haptex writes. What
// HDF5 can read is at most what the file holds on disk (a sparse hole counts for nothing: review 28,
// F4, a 540 KB file padded to 3 GB looped 86 s) and, once it is open, at most its end of address (zeros
// really on disk past it, as a copy or download of such a file has: review 29, F2, 73 s).
rlim_t processor_seconds(double bytes) {
  return rlim_t(haptex::kStuckCallSeconds + std::min(bytes / 50e6, 1e6));
}

double bytes_on_disk(const char* path) {
  struct stat s {};
  return ::stat(path, &s) == 0 ? double(std::min<off_t>(s.st_size, off_t(s.st_blocks) * 512)) : 0;
}

void set_limit(int resource, rlim_t value, rlim_t hard) {
  const rlimit limit{value, hard};
  setrlimit(resource, &limit);
}

// AddressSanitizer's runtime (HAPTEX_PROBE_SANITIZER: the compiler's libasan, found at configure time)
// preloaded: a read or copy past a heap block then stops the probe every time, not only when it happens
// to reach unmapped memory. Its errors abort (SIGABRT); a segmentation fault stays one. Not under a
// limit on address space (`ulimit -v`), which its shadow memory exceeds, nor when asked not to.
void start_again_under_sanitizer(char** argv) {
  const std::string runtime = HAPTEX_PROBE_SANITIZER;
  rlimit address_space{};
  if (runtime.empty() || ::access(runtime.c_str(), R_OK) != 0 || std::getenv("HAPTEX_PROBE_AS_IS") != nullptr ||
      getrlimit(RLIMIT_AS, &address_space) != 0 || address_space.rlim_cur != RLIM_INFINITY)
    return;
  std::vector<std::string> set = {
      "LD_PRELOAD=" + runtime, "HAPTEX_PROBE_AS_IS=1",
      "ASAN_OPTIONS=detect_leaks=0:abort_on_error=1:handle_segv=0:handle_sigbus=0:handle_abort=0:allocator_may_return_null=1:"
      "malloc_context_size=0:quarantine_size_mb=0"};
  std::vector<char*> environment;
  for (char** variable = environ; *variable != nullptr; ++variable) {
    const std::string_view name = std::string_view(*variable).substr(0, std::string_view(*variable).find('=') + 1);
    if (name != "LD_PRELOAD=" && name != "ASAN_OPTIONS=" && name != "HAPTEX_PROBE_AS_IS=") environment.push_back(*variable);
  }
  for (std::string& variable : set) environment.push_back(variable.data());
  environment.push_back(nullptr);
  // By its own path, not /proc/self/exe: the process keeps its name (ps, pgrep).
  std::array<char, 4096> self{};
  const ssize_t length = ::readlink("/proc/self/exe", self.data(), self.size() - 1);
  if (length > 0) ::execve(self.data(), argv, environment.data());  // when it fails, the probe runs as it is
}

// SIGXCPU at `seconds` of processor time (counted from the start), SIGKILL 5 s later. A probe that
// waits instead (a lock, a stalled disk) ends by SIGALRM, which haptex takes as no answer: it then reads
// the file itself, as without the probe.
void limit_time(rlim_t seconds) {
  set_limit(RLIMIT_CPU, seconds, seconds + 5);
  alarm(unsigned(4 * seconds));
}

}  // namespace

// HDF5 1.10 names a file it opens through a symbolic link by realpath(), and refuses to open it when
// that has no answer: the probe's /dev/fd/3 of a file renamed over since haptex opened it (its name
// "x.h5 (deleted)"), or one whose real path is longer than PATH_MAX (review 31, F1). The name serves
// only to resolve external links, which the probe never follows (check_links' rule), so for the probe's
// own file realpath answers with the name itself; any other name is resolved as usual.
extern "C" char* realpath(const char* __restrict name, char* __restrict resolved) noexcept {
  using Realpath = char* (*)(const char*, char*);
  static const auto next = reinterpret_cast<Realpath>(dlsym(RTLD_NEXT, "realpath"));
  if (name == nullptr || probed_name == nullptr || std::strcmp(name, probed_name) != 0) return next(name, resolved);
  if (resolved == nullptr) return strdup(name);
  if (std::strlen(name) >= PATH_MAX) {
    errno = ENAMETOOLONG;
    return nullptr;
  }
  return std::strcpy(resolved, name);
}

int main(int argc, char** argv) {
  const bool values = argc == 3 && std::string(argv[1]) == "--values";
  if (argc != 2 && !values) {
    std::cerr << "usage: haptex-h5-probe [--values] FILE (run by haptex before it reads an HDF5 file)\n";
    return 64;
  }
  const char* path = argv[argc - 1];
  probed_name = path;
  // Ends with its caller: haptex stopped by a signal sent to it alone (kill PID, a batch system's TERM)
  // leaves no probe running on (review 30, F3). (No check that the caller still lives: as process 1 of
  // a container, haptex is the parent whose pid is 1; review 31, F6.)
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  start_again_under_sanitizer(argv);
  set_limit(RLIMIT_CORE, 0, 0);  // a crash here is an answer, not a bug to keep a core of
  const double on_disk = bytes_on_disk(path);
  limit_time(processor_seconds(on_disk));
  const auto opened = [on_disk](std::uint64_t end_of_address) {
    limit_time(processor_seconds(std::min(on_disk, double(end_of_address))));
  };
  const int code = haptex::h5::read_structure(path, values ? haptex::h5::ProbeDepth::values : haptex::h5::ProbeDepth::structure,
                                              std::cout, opened);
  // No exit handlers: the libraries HDF5 loads (p11-kit through libcurl) deadlocked in theirs under the
  // sanitizer's runtime, and HDF5's own would close a file the probe leaves open on purpose.
  std::cout.flush();
  std::_Exit(code);
}
