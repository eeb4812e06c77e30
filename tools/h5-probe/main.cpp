// haptex-h5-probe [--values] FILE: reads the structure of an HDF5 file (with --values: its
// variable-length byte values) in a process of its own, so that damage crashing libhdf5 ends this
// program, not haptex (core/h5/structure_probe.hpp). Writes the place it reads next, NUL-ended, to
// standard output.
// Exit code 0 when all was read, 1 when HDF5 refused a read (its place, finding and fix follow), 3 when
// HDF5 could not open the file, 64 on a wrong command line; a signal when it crashed, SIGXCPU once it
// used its processor time (HDF5 loops on some damage), SIGALRM when it waited four times as long.
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <string>

#include "core/bounded_call.hpp"
#include "core/h5/structure_probe.hpp"

namespace {

// The processor time the probe may use: a reader's bound on one stuck call (kStuckCallSeconds), plus
// a second per 50 MB the file holds on disk, far slower than HDF5 reads any file haptex writes. What a
// sparse hole adds to its size counts for nothing (review 28, F4: a 540 KB file padded to 3 GB looped
// 86 s).
rlim_t processor_seconds(const char* path) {
  struct stat s {};
  const double megabytes = ::stat(path, &s) == 0 ? double(std::min<off_t>(s.st_size, off_t(s.st_blocks) * 512)) / 1e6 : 0;
  return rlim_t(haptex::kStuckCallSeconds + std::min(megabytes / 50, 1e6));
}

void set_limit(int resource, rlim_t value, rlim_t hard) {
  const rlimit limit{value, hard};
  setrlimit(resource, &limit);
}

}  // namespace

int main(int argc, char** argv) {
  const bool values = argc == 3 && std::string(argv[1]) == "--values";
  if (argc != 2 && !values) {
    std::cerr << "usage: haptex-h5-probe [--values] FILE (run by haptex before it reads an HDF5 file)\n";
    return 64;
  }
  const char* path = argv[argc - 1];
  set_limit(RLIMIT_CORE, 0, 0);  // a crash here is an answer, not a bug to keep a core of
  const rlim_t seconds = processor_seconds(path);
  set_limit(RLIMIT_CPU, seconds, seconds + 5);  // SIGXCPU at the soft limit, SIGKILL 5 s later
  // A probe that waits instead (a lock, a stalled disk) ends by SIGALRM, which haptex takes as no
  // answer: it then reads the file itself, as without the probe.
  alarm(unsigned(4 * seconds));
  const int code = haptex::h5::read_structure(path, values ? haptex::h5::ProbeDepth::values : haptex::h5::ProbeDepth::structure, std::cout);
  // No exit handlers: the libraries HDF5 loads (p11-kit through libcurl) deadlocked in theirs under the
  // sanitizer's runtime, and HDF5's own would close a file the probe leaves open on purpose.
  std::cout.flush();
  std::_Exit(code);
}
