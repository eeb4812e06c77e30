#include "core/open_files.hpp"

#include <fcntl.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cerrno>

#include "core/error.hpp"

namespace haptex {

unsigned long use_every_open_file_allowed() {
  rlimit limit{};
  if (getrlimit(RLIMIT_NOFILE, &limit) != 0) return 0;
  if (limit.rlim_cur < limit.rlim_max) {
    rlimit raised = limit;
    raised.rlim_cur = limit.rlim_max;
    if (setrlimit(RLIMIT_NOFILE, &raised) == 0) limit = raised;
  }
  return static_cast<unsigned long>(limit.rlim_cur);
}

int error_opening(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd >= 0) {
    ::close(fd);
    return 0;
  }
  const int error = errno;
  refuse_if_out_of_descriptors(error, path);
  return error;
}

void refuse_if_out_of_descriptors(int error, const std::string& path) {
  if (error != EMFILE && error != ENFILE) return;
  rlimit limit{};
  getrlimit(RLIMIT_NOFILE, &limit);
  const std::string who = error == EMFILE ? "haptex has as many files open as the system lets one program (ulimit -n " +
                                                std::to_string(limit.rlim_cur) + ")"
                                          : "the system has as many files open as it allows (fs.file-max)";
  throw failure(path + ": cannot open it: " + who + ". Raise the limit (ulimit -Hn, as root) or give fewer files at once");
}

}  // namespace haptex
