#pragma once
// One opened V4L2 video node: the file descriptor, what VIDIOC_QUERYCAP says about it, and the
// ioctl helper every other V4L2 file uses. Opening refuses nodes that cannot capture video, such
// as the metadata node UVC cameras (the GelSight Mini among them) expose beside the capture node.
#include <cstdint>
#include <string>

#include "capture/device/kernel_interface.hpp"

namespace haptex::capture {

struct DeviceIdentity {
  std::string path, card, driver, bus_info;
  std::uint32_t device_caps = 0;
};

class V4l2Device {
 public:
  // Opens non-blocking (streaming waits in poll, never in a blocking DQBUF). Throws haptex::Error
  // (bad_input) naming the node when it is missing, not accessible, or not a video capture node.
  V4l2Device(KernelInterface& kernel, std::string path);
  ~V4l2Device();
  V4l2Device(const V4l2Device&) = delete;
  V4l2Device& operator=(const V4l2Device&) = delete;

  KernelInterface& kernel() const { return kernel_; }
  int fd() const { return fd_; }
  const DeviceIdentity& identity() const { return identity_; }
  const std::string& path() const { return identity_.path; }

  // The ioctl, retried on EINTR; returns errno (0 on success) instead of throwing, because
  // several ioctls fail by design (EINVAL ends every enumeration).
  int try_ioctl(unsigned long request, void* arg) const;
  // The same, throwing haptex::Error (failed) naming the node and `what` on any error.
  void ioctl_or_throw(unsigned long request, void* arg, const std::string& what) const;

 private:
  void query_capabilities();
  KernelInterface& kernel_;
  int fd_ = -1;
  DeviceIdentity identity_;
};

}  // namespace haptex::capture
