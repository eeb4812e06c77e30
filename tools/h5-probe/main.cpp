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
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <string>

#include "core/bounded_call.hpp"
#include "core/h5/structure_probe.hpp"

namespace {

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

// SIGXCPU at `seconds` of processor time (counted from the start), SIGKILL 5 s later. A probe that
// waits instead (a lock, a stalled disk) ends by SIGALRM, which haptex takes as no answer: it then reads
// the file itself, as without the probe.
void limit_time(rlim_t seconds) {
  set_limit(RLIMIT_CPU, seconds, seconds + 5);
  alarm(unsigned(4 * seconds));
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
