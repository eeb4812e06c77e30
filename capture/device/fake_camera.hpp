#pragma once
// A UVC camera behind KernelInterface: formats, frame sizes and rates, controls with automatic
// modes, mmap buffers, poll and DQBUF, and the faults real sensors show (lost frames, buffers flagged
// V4L2_BUF_FLAG_ERROR, corrupt payloads, stalls, unplugging). Tests and benchmarks use it in place of
// a GelSight, and `haptex capture record --device fake:...` lets a user try the recorder without one.
//
// Time: in lockstep mode every poll that finds a free buffer produces the next frame at once, with
// timestamps one period apart, so tests are exact and fast. In real-time mode frames fall due on the
// wall clock (optionally `speed` times faster), and a frame that finds no free buffer is lost, as
// with a real driver: that is how host-side drops are measured.
//
// What it films is pluggable (camera_scene.hpp): the synthetic gel of fake_scene.hpp by default, or
// a replayed file (capture/replay/). A scene that ends ends the stream as V4L2 ends a finite one
// (a decoder draining): an empty buffer flagged V4L2_BUF_FLAG_LAST, then EPIPE from every DQBUF.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "capture/device/camera_scene.hpp"
#include "capture/device/fake_scene.hpp"
#include "capture/device/kernel_interface.hpp"

namespace haptex::capture {

struct FakeMode {
  std::uint32_t fourcc = 0;
  std::uint32_t width = 0, height = 0;
  std::vector<double> fps;
  // Bytes a buffer holds (sizeimage); 0: width x height for MJPG (room for the fake's JPEGs), the
  // frame's size for YUYV. A payload longer than this arrives cut off, as from a real driver.
  std::uint32_t max_payload = 0;
};

struct FakeControl {
  std::uint32_t id = 0;
  std::int32_t minimum = 0, maximum = 0, step = 1, default_value = 0, value = 0;
  std::uint32_t type = 1;  // V4L2_CTRL_TYPE_INTEGER
};

struct FakeStall {
  std::uint64_t before_frame = 0;  // scene frame that comes late
  int duration_ms = 0;
};

struct FakeCameraConfig {
  std::string capture_path = "/dev/video0";
  std::string metadata_path = "/dev/video1";  // opens, but QUERYCAP says metadata capture only
  std::string card = "GelSight Mini R0B 2BNK-CE6G: Ge", driver = "uvcvideo", bus_info = "usb-0000:00:14.0-2";
  std::vector<FakeMode> modes;          // default: the GelSight Mini's only mode, MJPG 3280 x 2464 at 25 fps
  std::vector<FakeControl> controls;    // default: the UVC exposure, white balance and gain controls
  bool can_set_rate = true;             // V4L2_CAP_TIMEPERFRAME
  unsigned max_buffers = 8;             // REQBUFS grants at most this many
  double drop_percent = 0;              // frames the camera loses before the host sees them
  double error_percent = 0;             // buffers returned with V4L2_BUF_FLAG_ERROR
  double corrupt_percent = 0;           // payloads cut to a third, without an error flag
  std::optional<std::uint64_t> disconnect_after;  // ENODEV once this many frames were produced
  std::vector<FakeStall> stalls;
  bool realtime = false;
  double speed = 1.0;                   // real-time mode: frames come this many times faster
  PressSchedule scene;
  std::uint64_t seed = 1;
  // What the camera films in the granted mode, made anew at every STREAMON (V4L2 restarts the
  // sequence there). Empty: the synthetic FakeScene of `scene` and `seed`.
  std::function<std::unique_ptr<CameraScene>(const FakeMode& mode)> film;
};

// Defaults shared by the fake and its tests.
FakeMode gelsight_mini_mode();
std::vector<FakeControl> uvc_controls();

struct FakeCameraStats {
  std::uint64_t produced = 0;        // frames the sensor made (= the next sequence number)
  std::uint64_t delivered = 0;       // handed to the host through DQBUF
  std::uint64_t camera_drops = 0;    // drop_percent
  std::uint64_t host_drops = 0;      // lost because every buffer was still with the host
  std::uint64_t error_buffers = 0;
  std::uint64_t corrupt_payloads = 0;
};

class FakeCamera : public KernelInterface {
 public:
  explicit FakeCamera(FakeCameraConfig config = {});
  ~FakeCamera() override;

  int open(const char* path, int flags) override;
  int close(int fd) override;
  int ioctl(int fd, unsigned long request, void* arg) override;
  void* mmap(void* address, std::size_t length, int protection, int flags, int fd, off_t offset) override;
  int munmap(void* address, std::size_t length) override;
  int poll(pollfd* fds, nfds_t count, int timeout_ms) override;

  const FakeCameraStats& stats() const;
  const FakeCameraConfig& config() const;
  std::int32_t control_value(std::uint32_t id) const;
  std::size_t mapped_buffers() const;
  std::size_t open_descriptors() const;
  bool streaming() const;
  // The synthetic scene behind the granted format (made at the first STREAMON), nullptr before and
  // when the camera films something else (config.film).
  const FakeScene* scene() const;

 private:
  struct State;  // buffers, queues, clocks and controls: fake_camera.cpp
  std::unique_ptr<State> state_;
};

}  // namespace haptex::capture
