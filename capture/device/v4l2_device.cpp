#include "capture/device/v4l2_device.hpp"

#include <fcntl.h>
#include <linux/videodev2.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "core/error.hpp"
#include "core/text/format.hpp"

namespace haptex::capture {
namespace {

std::string fixed_string(const __u8* bytes, std::size_t size) {
  const char* text = reinterpret_cast<const char*>(bytes);
  return std::string(text, strnlen(text, size));
}

std::string hex(std::uint32_t value) {
  return text::format("0x%08x", value);
}

void throw_open_error(const std::string& path, int error) {
  const std::string reason = std::strerror(error);
  if (error == ENOENT)
    throw input_error(path, "", "no such video device", "List the connected sensors with 'haptex capture devices'");
  if (error == EACCES || error == EPERM)
    throw input_error(path, "", "permission denied (" + reason + ")",
                      "Add your user to the 'video' group (sudo usermod -aG video $USER) and log in again");
  if (error == EBUSY)
    throw input_error(path, "", "the device is busy", "Close the other program using the camera and retry");
  throw input_error(path, "", "cannot open the video device (" + reason + ")", "Check the node with 'v4l2-ctl -d " + path + " --all'");
}

}  // namespace

V4l2Device::V4l2Device(KernelInterface& kernel, std::string path) : kernel_(kernel) {
  identity_.path = std::move(path);
  fd_ = kernel_.open(identity_.path.c_str(), O_RDWR | O_NONBLOCK | O_CLOEXEC);
  if (fd_ < 0) throw_open_error(identity_.path, errno);
  try {
    query_capabilities();
  } catch (...) {
    kernel_.close(fd_);
    throw;
  }
}

V4l2Device::~V4l2Device() {
  if (fd_ >= 0) kernel_.close(fd_);
}

int V4l2Device::try_ioctl(unsigned long request, void* arg) const {
  for (;;) {
    if (kernel_.ioctl(fd_, request, arg) == 0) return 0;
    if (errno != EINTR) return errno;
  }
}

void V4l2Device::ioctl_or_throw(unsigned long request, void* arg, const std::string& what) const {
  const int error = try_ioctl(request, arg);
  if (error != 0) throw failure(identity_.path + ": " + what + " failed: " + std::strerror(error));
}

void V4l2Device::query_capabilities() {
  v4l2_capability caps{};
  const int error = try_ioctl(VIDIOC_QUERYCAP, &caps);
  if (error != 0)
    throw input_error(identity_.path, "VIDIOC_QUERYCAP", std::string("not a V4L2 device (") + std::strerror(error) + ")",
                      "Give a /dev/videoN node; 'haptex capture devices' lists the sensors' capture nodes");
  identity_.card = fixed_string(caps.card, sizeof caps.card);
  identity_.driver = fixed_string(caps.driver, sizeof caps.driver);
  identity_.bus_info = fixed_string(caps.bus_info, sizeof caps.bus_info);
  // device_caps describe this node; capabilities describe the whole physical device.
  identity_.device_caps = (caps.capabilities & V4L2_CAP_DEVICE_CAPS) ? caps.device_caps : caps.capabilities;
  const std::uint32_t dc = identity_.device_caps;
  if (!(dc & V4L2_CAP_VIDEO_CAPTURE)) {
    const bool metadata = dc & V4L2_CAP_META_CAPTURE;
    throw input_error(identity_.path, "VIDIOC_QUERYCAP",
                      "'" + identity_.card + "' node cannot capture video (device caps " + hex(dc) +
                          (metadata ? ", metadata capture only: this is probably the sensor's metadata node" : "") + ")",
                      "Use the sensor's capture node, usually the other /dev/videoN of the pair with the lower number; "
                      "'haptex capture devices' names it");
  }
  if (!(dc & V4L2_CAP_STREAMING))
    throw input_error(identity_.path, "VIDIOC_QUERYCAP", "'" + identity_.card + "' does not support streaming I/O",
                      "haptex needs a camera with mmap streaming (every UVC camera has it)");
}

}  // namespace haptex::capture
