#pragma once
// The real system calls behind KernelInterface.
#include "capture/device/kernel_interface.hpp"

namespace haptex::capture {

class SystemKernel : public KernelInterface {
 public:
  int open(const char* path, int flags) override;
  int close(int fd) override;
  int ioctl(int fd, unsigned long request, void* arg) override;
  void* mmap(void* address, std::size_t length, int protection, int flags, int fd, off_t offset) override;
  int munmap(void* address, std::size_t length) override;
  int poll(pollfd* fds, nfds_t count, int timeout_ms) override;
};

}  // namespace haptex::capture
