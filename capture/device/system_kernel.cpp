#include "capture/device/system_kernel.hpp"

#include <fcntl.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <unistd.h>

namespace haptex::capture {

int SystemKernel::open(const char* path, int flags) { return ::open(path, flags); }
int SystemKernel::close(int fd) { return ::close(fd); }
int SystemKernel::ioctl(int fd, unsigned long request, void* arg) { return ::ioctl(fd, request, arg); }
void* SystemKernel::mmap(void* address, std::size_t length, int protection, int flags, int fd, off_t offset) {
  return ::mmap(address, length, protection, flags, fd, offset);
}
int SystemKernel::munmap(void* address, std::size_t length) { return ::munmap(address, length); }
int SystemKernel::poll(pollfd* fds, nfds_t count, int timeout_ms) { return ::poll(fds, count, timeout_ms); }

}  // namespace haptex::capture
