#pragma once
// Every file descriptor this process may open taken, for a test of what a run out of them says
// (core/open_files.hpp): the soft limit is set to the lowest free descriptor, so that every open fails
// with EMFILE. Restored when it goes out of scope.
#include <fcntl.h>
#include <sys/resource.h>
#include <unistd.h>

namespace haptex::test {

class NoFreeDescriptor {
 public:
  NoFreeDescriptor() {
    getrlimit(RLIMIT_NOFILE, &before_);
    const int lowest_free = ::open("/dev/null", O_RDONLY);
    ::close(lowest_free);
    rlimit none = before_;
    none.rlim_cur = rlim_t(lowest_free);
    setrlimit(RLIMIT_NOFILE, &none);
  }
  ~NoFreeDescriptor() { setrlimit(RLIMIT_NOFILE, &before_); }
  NoFreeDescriptor(const NoFreeDescriptor&) = delete;
  NoFreeDescriptor& operator=(const NoFreeDescriptor&) = delete;

 private:
  rlimit before_{};
};

}  // namespace haptex::test
