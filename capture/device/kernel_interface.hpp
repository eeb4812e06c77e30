#pragma once
// The narrowest seam between haptex and a camera: the six system calls V4L2 capture needs.
// SystemKernel (system_kernel.hpp) makes the real calls; FakeCamera (fake_camera.hpp) answers them
// like a UVC driver would, so everything above this line is tested without hardware.
// Every function behaves like the system call of the same name: -1 (or MAP_FAILED) and errno on failure.
#include <poll.h>
#include <sys/types.h>

#include <cstddef>

namespace haptex::capture {

class KernelInterface {
 public:
  virtual ~KernelInterface() = default;
  virtual int open(const char* path, int flags) = 0;
  virtual int close(int fd) = 0;
  virtual int ioctl(int fd, unsigned long request, void* arg) = 0;
  virtual void* mmap(void* address, std::size_t length, int protection, int flags, int fd, off_t offset) = 0;
  virtual int munmap(void* address, std::size_t length) = 0;
  virtual int poll(pollfd* fds, nfds_t count, int timeout_ms) = 0;
};

}  // namespace haptex::capture
