#include "capture/device/fake_camera.hpp"

#include <linux/videodev2.h>
#include <sys/mman.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <deque>
#include <map>
#include <thread>
#include <tuple>

namespace haptex::capture {
namespace {

using Clock = std::chrono::steady_clock;
constexpr std::size_t kPage = 4096;

int fail(int error) {
  errno = error;
  return -1;
}

void copy_text(__u8* out, std::size_t size, const std::string& text) {
  std::memset(out, 0, size);
  std::memcpy(out, text.data(), std::min(size - 1, text.size()));
}

std::uint32_t image_size(const FakeMode& m) {
  if (m.max_payload) return m.max_payload;
  return m.fourcc == V4L2_PIX_FMT_YUYV ? m.width * m.height * 2 : m.width * m.height;  // MJPG: room for the fake's JPEGs
}

v4l2_fract interval_of(double fps) {
  const bool whole = std::abs(fps - std::round(fps)) < 1e-6;
  return whole ? v4l2_fract{1, std::uint32_t(std::lround(fps))} : v4l2_fract{1000, std::uint32_t(std::lround(fps * 1000))};
}

}  // namespace

FakeMode gelsight_mini_mode() { return {V4L2_PIX_FMT_MJPEG, 3280, 2464, {25.0}}; }

std::vector<FakeControl> uvc_controls() {
  return {
      {V4L2_CID_EXPOSURE_AUTO, 0, 3, 1, 3, 3, V4L2_CTRL_TYPE_MENU},  // UVC: 1 manual, 3 aperture priority
      {V4L2_CID_EXPOSURE_ABSOLUTE, 1, 5000, 1, 157, 166, V4L2_CTRL_TYPE_INTEGER},
      {V4L2_CID_EXPOSURE_AUTO_PRIORITY, 0, 1, 1, 0, 1, V4L2_CTRL_TYPE_BOOLEAN},
      {V4L2_CID_AUTO_WHITE_BALANCE, 0, 1, 1, 1, 1, V4L2_CTRL_TYPE_BOOLEAN},
      {V4L2_CID_WHITE_BALANCE_TEMPERATURE, 2800, 6500, 10, 4600, 5120, V4L2_CTRL_TYPE_INTEGER},
      {V4L2_CID_GAIN, 0, 100, 1, 0, 32, V4L2_CTRL_TYPE_INTEGER},
      {V4L2_CID_BRIGHTNESS, -64, 64, 1, 0, 0, V4L2_CTRL_TYPE_INTEGER},
  };
}

struct FakeCamera::State {
  struct Buffer {
    std::unique_ptr<std::uint8_t[]> memory;
    std::size_t length = 0;
    std::uint32_t offset = 0;
    bool queued = false, done = false, mapped = false;
  };
  struct Completed {
    std::uint32_t index, bytes_used, sequence, flags;
    std::int64_t timestamp_ns;
  };

  FakeCameraConfig config;
  FakeCameraStats stats;
  std::map<int, bool> descriptors;  // fd -> is the capture node
  int next_fd = 100;

  FakeMode mode;
  double fps = 0;
  std::vector<Buffer> buffers;
  std::deque<std::uint32_t> queued;
  std::deque<Completed> done;
  bool streaming = false, disconnected = false;
  std::unique_ptr<CameraScene> scene;
  // The end of a finite scene: it had no more frames; the empty LAST buffer is in `done`; the host
  // dequeued it (from then on DQBUF fails with EPIPE, as vb2 does).
  bool scene_ended = false, last_queued = false, last_dequeued = false;

  std::uint64_t next_frame = 0;
  std::int64_t camera_t0_ns = 0, lockstep_now_ns = 0;
  Clock::time_point wall_t0;
  // Real time: how long the scene took to make its frames (decoding a replayed file). The camera's
  // schedule waits for it, so a scene slower than the rate plays slower instead of filling every
  // buffer while the host, which shares this thread, had no chance to take a frame.
  Clock::duration scene_time{};
  std::mt19937_64 rng;

  explicit State(FakeCameraConfig c) : config(std::move(c)), rng(config.seed) {
    if (config.modes.empty()) config.modes = {gelsight_mini_mode()};
    if (config.controls.empty()) config.controls = uvc_controls();
    mode = config.modes.front();
    fps = mode.fps.front();
  }

  double period_ns() const { return 1e9 / fps; }
  bool chance(double percent) { return percent > 0 && std::uniform_real_distribution<double>(0, 100)(rng) < percent; }

  // Camera time of scene frame k since STREAMON: one period per frame, plus the stalls before it.
  std::int64_t frame_time_ns(std::uint64_t k) const {
    double t = double(k) * period_ns();
    for (const auto& s : config.stalls)
      if (s.before_frame <= k) t += s.duration_ms * 1e6;
    return std::int64_t(t);
  }

  FakeControl* control(std::uint32_t id) {
    for (auto& c : config.controls)
      if (c.id == id) return &c;
    return nullptr;
  }

  // The sensor makes frame next_frame; it reaches a buffer unless it is lost on the way.
  void produce_one() {
    if (config.disconnect_after && stats.produced >= *config.disconnect_after) {
      disconnected = true;
      return;
    }
    const Clock::time_point asked = Clock::now();
    const std::vector<std::uint8_t>* payload = scene->frame(next_frame);
    if (config.realtime) scene_time += Clock::now() - asked;
    if (!payload) {
      scene_ended = true;
      return;
    }
    const std::uint64_t k = next_frame++;
    ++stats.produced;
    if (chance(config.drop_percent)) {
      ++stats.camera_drops;
      return;
    }
    if (queued.empty()) {
      ++stats.host_drops;
      return;
    }
    const std::uint32_t index = queued.front();
    queued.pop_front();
    Buffer& b = buffers[index];
    std::uint32_t bytes = std::uint32_t(std::min(payload->size(), b.length));
    std::uint32_t flags = V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC | V4L2_BUF_FLAG_TSTAMP_SRC_SOE | V4L2_BUF_FLAG_DONE;
    if (chance(config.error_percent)) {
      ++stats.error_buffers;
      flags |= V4L2_BUF_FLAG_ERROR;
      bytes /= 2;
    } else if (chance(config.corrupt_percent)) {
      ++stats.corrupt_payloads;
      bytes /= 3;
    }
    std::memcpy(b.memory.get(), payload->data(), bytes);
    b.queued = false;
    b.done = true;
    done.push_back({index, bytes, std::uint32_t(k), flags, camera_t0_ns + frame_time_ns(k)});
  }

  // After the scene's last frame the next free buffer comes back empty and flagged LAST: how a V4L2
  // driver with a finite stream (a decoder draining) says there will be no more.
  void queue_last_buffer() {
    if (last_queued || queued.empty()) return;
    const std::uint32_t index = queued.front();
    queued.pop_front();
    buffers[index].queued = false;
    buffers[index].done = true;
    const std::uint32_t flags = V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC | V4L2_BUF_FLAG_DONE | V4L2_BUF_FLAG_LAST;
    done.push_back({index, 0, std::uint32_t(next_frame), flags, camera_t0_ns + frame_time_ns(next_frame)});
    last_queued = true;
  }

  short poll_lockstep(int timeout_ms) {
    const std::int64_t timeout_ns = std::int64_t(timeout_ms) * 1000000, deadline_ns = lockstep_now_ns + timeout_ns;
    for (;;) {
      if (!done.empty() || last_dequeued) return POLLIN | POLLRDNORM;  // after LAST: readable, DQBUF says EPIPE
      if (disconnected) return POLLERR | POLLHUP;
      if (!streaming) return POLLERR;
      if (scene_ended) {
        queue_last_buffer();
        if (done.empty()) return 0;  // the host holds every buffer
        continue;
      }
      const std::int64_t due = frame_time_ns(next_frame);
      // A stall longer than the poll timeout, or frames all dropped until it passed, is seen as a
      // timeout that moves the clock on (review 6: with drop=100 one poll produced frames forever).
      if (due > deadline_ns) {
        lockstep_now_ns = deadline_ns;
        return 0;
      }
      if (queued.empty()) return 0;  // the host holds every buffer: nothing can arrive
      lockstep_now_ns = std::max(lockstep_now_ns, due);
      produce_one();
    }
  }

  Clock::time_point wall_due(std::uint64_t k) const {
    return wall_t0 + scene_time + std::chrono::nanoseconds(std::int64_t(double(frame_time_ns(k)) / config.speed));
  }

  short poll_realtime(int timeout_ms) {
    const Clock::time_point deadline = Clock::now() + std::chrono::milliseconds(timeout_ms);
    for (;;) {
      const Clock::time_point now = Clock::now();
      // Frames falling due are made until the poll's deadline, never past it: a scene slow to render
      // (a large frame) must not keep the recorder from its loop, which reads --seconds and Ctrl-C.
      while (streaming && !disconnected && !scene_ended && wall_due(next_frame) <= now && Clock::now() < deadline) produce_one();
      if (streaming && scene_ended) queue_last_buffer();
      if (!done.empty() || last_dequeued) return POLLIN | POLLRDNORM;
      if (disconnected) return POLLERR | POLLHUP;
      if (!streaming) return POLLERR;
      if (now >= deadline) return 0;
      // Once the scene has ended nothing falls due: only a buffer given back could change anything.
      std::this_thread::sleep_until(scene_ended ? deadline : std::min(wall_due(next_frame), deadline));
    }
  }

  // ---- ioctl handlers

  int querycap(bool capture_node, v4l2_capability* caps) {
    *caps = {};
    copy_text(caps->driver, sizeof caps->driver, config.driver);
    copy_text(caps->card, sizeof caps->card, config.card);
    copy_text(caps->bus_info, sizeof caps->bus_info, config.bus_info);
    caps->version = 0x060100;
    caps->capabilities = V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_META_CAPTURE | V4L2_CAP_STREAMING | V4L2_CAP_DEVICE_CAPS;
    caps->device_caps = capture_node ? V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_STREAMING | V4L2_CAP_EXT_PIX_FORMAT
                                     : V4L2_CAP_META_CAPTURE | V4L2_CAP_STREAMING | V4L2_CAP_EXT_PIX_FORMAT;
    return 0;
  }

  std::vector<std::uint32_t> fourccs() const {
    std::vector<std::uint32_t> out;
    for (const auto& m : config.modes)
      if (std::find(out.begin(), out.end(), m.fourcc) == out.end()) out.push_back(m.fourcc);
    return out;
  }

  int enum_fmt(v4l2_fmtdesc* d) {
    const auto list = fourccs();
    if (d->type != V4L2_BUF_TYPE_VIDEO_CAPTURE || d->index >= list.size()) return fail(EINVAL);
    d->pixelformat = list[d->index];
    d->flags = d->pixelformat == V4L2_PIX_FMT_MJPEG ? V4L2_FMT_FLAG_COMPRESSED : 0;
    copy_text(d->description, sizeof d->description, d->pixelformat == V4L2_PIX_FMT_MJPEG ? "Motion-JPEG" : "YUYV 4:2:2");
    return 0;
  }

  std::vector<const FakeMode*> modes_of(std::uint32_t fourcc) const {
    std::vector<const FakeMode*> out;
    for (const auto& m : config.modes)
      if (m.fourcc == fourcc) out.push_back(&m);
    return out;
  }

  int enum_framesizes(v4l2_frmsizeenum* e) {
    const auto list = modes_of(e->pixel_format);
    if (e->index >= list.size()) return fail(EINVAL);
    e->type = V4L2_FRMSIZE_TYPE_DISCRETE;
    e->discrete = {list[e->index]->width, list[e->index]->height};
    return 0;
  }

  int enum_frameintervals(v4l2_frmivalenum* e) {
    for (const FakeMode* m : modes_of(e->pixel_format)) {
      if (m->width != e->width || m->height != e->height) continue;
      if (e->index >= m->fps.size()) return fail(EINVAL);
      e->type = V4L2_FRMIVAL_TYPE_DISCRETE;
      e->discrete = interval_of(m->fps[e->index]);
      return 0;
    }
    return fail(EINVAL);
  }

  void fill_format(v4l2_format* f) const {
    f->fmt.pix.pixelformat = mode.fourcc;
    f->fmt.pix.width = mode.width;
    f->fmt.pix.height = mode.height;
    f->fmt.pix.field = V4L2_FIELD_NONE;
    f->fmt.pix.bytesperline = mode.fourcc == V4L2_PIX_FMT_YUYV ? mode.width * 2 : 0;
    f->fmt.pix.sizeimage = image_size(mode);
    f->fmt.pix.colorspace = V4L2_COLORSPACE_SRGB;
  }

  // Like UVC: an unknown format becomes the first offered, a size the nearest offered.
  FakeMode nearest_mode(const v4l2_pix_format& want) const {
    auto list = modes_of(want.pixelformat);
    if (list.empty()) list = modes_of(config.modes.front().fourcc);
    const FakeMode* best = list.front();
    auto distance = [&](const FakeMode* m) {
      return std::abs(double(m->width) - want.width) + std::abs(double(m->height) - want.height);
    };
    for (const FakeMode* m : list)
      if (distance(m) < distance(best)) best = m;
    return *best;
  }

  int set_format(v4l2_format* f, bool try_only) {
    if (f->type != V4L2_BUF_TYPE_VIDEO_CAPTURE) return fail(EINVAL);
    if (!try_only && (streaming || !buffers.empty())) return fail(EBUSY);
    const FakeMode chosen = nearest_mode(f->fmt.pix);
    if (!try_only) {
      mode = chosen;
      fps = mode.fps.front();
    }
    const FakeMode saved = mode;
    mode = chosen;
    fill_format(f);
    mode = saved;
    return 0;
  }

  int get_parm(v4l2_streamparm* p) {
    if (p->type != V4L2_BUF_TYPE_VIDEO_CAPTURE) return fail(EINVAL);
    p->parm.capture = {};
    p->parm.capture.capability = config.can_set_rate ? V4L2_CAP_TIMEPERFRAME : 0;
    p->parm.capture.timeperframe = interval_of(fps);
    p->parm.capture.readbuffers = 0;
    return 0;
  }

  int set_parm(v4l2_streamparm* p) {
    if (p->type != V4L2_BUF_TYPE_VIDEO_CAPTURE) return fail(EINVAL);
    if (!config.can_set_rate) return fail(ENOTTY);
    if (streaming) return fail(EBUSY);
    const v4l2_fract want = p->parm.capture.timeperframe;
    const double wanted = want.numerator ? double(want.denominator) / want.numerator : mode.fps.front();
    double best = mode.fps.front();
    for (double f : mode.fps)
      if (std::abs(f - wanted) < std::abs(best - wanted)) best = f;
    fps = best;
    return get_parm(p);
  }

  int query_control(v4l2_queryctrl* q) {
    const FakeControl* c = control(q->id);
    if (!c) return fail(EINVAL);
    const std::uint32_t id = q->id;
    *q = {};
    q->id = id;
    q->type = c->type;
    q->minimum = c->minimum;
    q->maximum = c->maximum;
    q->step = c->step;
    q->default_value = c->default_value;
    return 0;
  }

  bool automatic(std::uint32_t auto_id, std::int32_t manual) {
    const FakeControl* a = control(auto_id);
    return a && a->value != manual;
  }

  int set_control(v4l2_control* v) {
    FakeControl* c = control(v->id);
    if (!c) return fail(EINVAL);
    if (v->value < c->minimum || v->value > c->maximum) return fail(ERANGE);
    if (c->id == V4L2_CID_EXPOSURE_AUTO && v->value != V4L2_EXPOSURE_MANUAL && v->value != V4L2_EXPOSURE_APERTURE_PRIORITY)
      return fail(EINVAL);
    // Like UVC, a value its automatic loop owns cannot be written while the loop runs.
    if ((c->id == V4L2_CID_EXPOSURE_ABSOLUTE && automatic(V4L2_CID_EXPOSURE_AUTO, V4L2_EXPOSURE_MANUAL)) ||
        (c->id == V4L2_CID_WHITE_BALANCE_TEMPERATURE && automatic(V4L2_CID_AUTO_WHITE_BALANCE, 0)) ||
        (c->id == V4L2_CID_GAIN && automatic(V4L2_CID_AUTOGAIN, 0)))
      return fail(EBUSY);
    c->value = v->value;
    return 0;
  }

  int request_buffers(v4l2_requestbuffers* r) {
    if (r->type != V4L2_BUF_TYPE_VIDEO_CAPTURE || r->memory != V4L2_MEMORY_MMAP) return fail(EINVAL);
    if (streaming) return fail(EBUSY);
    for (const auto& b : buffers)
      if (b.mapped) return fail(EBUSY);
    buffers.clear();
    queued.clear();
    done.clear();
    r->count = std::min(r->count, config.max_buffers);
    const std::size_t length = image_size(mode);
    const std::size_t stride = (length + kPage - 1) / kPage * kPage;
    for (std::uint32_t i = 0; i < r->count; ++i) {
      Buffer b;
      b.memory.reset(new std::uint8_t[length]);  // not zeroed: pages are only touched when a payload lands
      b.length = length;
      b.offset = std::uint32_t(i * stride);
      buffers.push_back(std::move(b));
    }
    return 0;
  }

  void describe(std::uint32_t index, v4l2_buffer* out) const {
    const Buffer& b = buffers[index];
    out->length = std::uint32_t(b.length);
    out->m.offset = b.offset;
    out->flags = (b.queued ? V4L2_BUF_FLAG_QUEUED : 0) | (b.done ? V4L2_BUF_FLAG_DONE : 0) |
                 (b.mapped ? V4L2_BUF_FLAG_MAPPED : 0);
  }

  int query_buffer(v4l2_buffer* b) {
    if (b->type != V4L2_BUF_TYPE_VIDEO_CAPTURE || b->index >= buffers.size()) return fail(EINVAL);
    describe(b->index, b);
    return 0;
  }

  int queue_buffer(v4l2_buffer* b) {
    if (b->type != V4L2_BUF_TYPE_VIDEO_CAPTURE || b->memory != V4L2_MEMORY_MMAP || b->index >= buffers.size())
      return fail(EINVAL);
    Buffer& buffer = buffers[b->index];
    if (buffer.queued || buffer.done) return fail(EINVAL);
    buffer.queued = true;
    queued.push_back(b->index);
    return 0;
  }

  int dequeue_buffer(v4l2_buffer* b) {
    if (b->type != V4L2_BUF_TYPE_VIDEO_CAPTURE || b->memory != V4L2_MEMORY_MMAP) return fail(EINVAL);
    if (done.empty()) return fail(disconnected ? ENODEV : last_dequeued ? EPIPE : streaming ? EAGAIN : EINVAL);
    const Completed c = done.front();
    done.pop_front();
    buffers[c.index].done = false;
    if (c.flags & V4L2_BUF_FLAG_LAST) last_dequeued = true;
    ++stats.delivered;
    describe(c.index, b);
    b->index = c.index;
    b->bytesused = c.bytes_used;
    b->sequence = c.sequence;
    b->flags = c.flags;
    b->field = V4L2_FIELD_NONE;
    b->timestamp.tv_sec = c.timestamp_ns / 1000000000;
    b->timestamp.tv_usec = (c.timestamp_ns % 1000000000) / 1000;
    return 0;
  }

  int stream_on() {
    if (buffers.empty()) return fail(EINVAL);
    if (streaming) return 0;
    if (config.film) {
      scene = config.film(mode);
    } else if (!scene || scene_key != std::make_tuple(mode.fourcc, mode.width, mode.height)) {
      // Rendering the synthetic scene's payloads is costly at full size: kept while the mode stays.
      scene = std::make_unique<FakeScene>(mode.fourcc, int(mode.width), int(mode.height), config.scene, config.seed);
      scene_key = std::make_tuple(mode.fourcc, mode.width, mode.height);
    }
    streaming = true;
    scene_ended = last_queued = last_dequeued = false;
    next_frame = 0;  // V4L2 restarts the sequence at every STREAMON
    lockstep_now_ns = 0;
    camera_t0_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now().time_since_epoch()).count();
    wall_t0 = Clock::now();
    scene_time = {};
    return 0;
  }

  int stream_off() {
    streaming = false;
    last_dequeued = false;
    queued.clear();
    done.clear();
    for (auto& b : buffers) b.queued = b.done = false;
    return 0;
  }

  std::tuple<std::uint32_t, std::uint32_t, std::uint32_t> scene_key{0, 0, 0};

  int handle(bool capture_node, unsigned long request, void* arg) {
    if (request == VIDIOC_QUERYCAP) return disconnected ? fail(ENODEV) : querycap(capture_node, static_cast<v4l2_capability*>(arg));
    if (!capture_node) return fail(ENOTTY);
    // Frames that reached the host's queue before the unplug can still be dequeued.
    if (request == VIDIOC_DQBUF) return dequeue_buffer(static_cast<v4l2_buffer*>(arg));
    if (disconnected) return fail(ENODEV);
    switch (request) {
      case VIDIOC_ENUM_FMT: return enum_fmt(static_cast<v4l2_fmtdesc*>(arg));
      case VIDIOC_ENUM_FRAMESIZES: return enum_framesizes(static_cast<v4l2_frmsizeenum*>(arg));
      case VIDIOC_ENUM_FRAMEINTERVALS: return enum_frameintervals(static_cast<v4l2_frmivalenum*>(arg));
      case VIDIOC_G_FMT: fill_format(static_cast<v4l2_format*>(arg)); return 0;
      case VIDIOC_S_FMT: return set_format(static_cast<v4l2_format*>(arg), false);
      case VIDIOC_TRY_FMT: return set_format(static_cast<v4l2_format*>(arg), true);
      case VIDIOC_G_PARM: return get_parm(static_cast<v4l2_streamparm*>(arg));
      case VIDIOC_S_PARM: return set_parm(static_cast<v4l2_streamparm*>(arg));
      case VIDIOC_QUERYCTRL: return query_control(static_cast<v4l2_queryctrl*>(arg));
      case VIDIOC_G_CTRL: {
        auto* v = static_cast<v4l2_control*>(arg);
        const FakeControl* c = control(v->id);
        if (!c) return fail(EINVAL);
        v->value = c->value;
        return 0;
      }
      case VIDIOC_S_CTRL: return set_control(static_cast<v4l2_control*>(arg));
      case VIDIOC_REQBUFS: return request_buffers(static_cast<v4l2_requestbuffers*>(arg));
      case VIDIOC_QUERYBUF: return query_buffer(static_cast<v4l2_buffer*>(arg));
      case VIDIOC_QBUF: return queue_buffer(static_cast<v4l2_buffer*>(arg));
      case VIDIOC_STREAMON: return stream_on();
      case VIDIOC_STREAMOFF: return stream_off();
      default: return fail(ENOTTY);
    }
  }
};

FakeCamera::FakeCamera(FakeCameraConfig config) : state_(std::make_unique<State>(std::move(config))) {}
FakeCamera::~FakeCamera() = default;

int FakeCamera::open(const char* path, int) {
  State& s = *state_;
  const std::string p = path;
  if (p != s.config.capture_path && p != s.config.metadata_path) return fail(ENOENT);
  if (s.disconnected) return fail(ENODEV);
  const int fd = s.next_fd++;
  s.descriptors[fd] = p == s.config.capture_path;
  return fd;
}

int FakeCamera::close(int fd) {
  State& s = *state_;
  const auto it = s.descriptors.find(fd);
  if (it == s.descriptors.end()) return fail(EBADF);
  if (it->second) s.stream_off();
  s.descriptors.erase(it);
  return 0;
}

int FakeCamera::ioctl(int fd, unsigned long request, void* arg) {
  State& s = *state_;
  const auto it = s.descriptors.find(fd);
  if (it == s.descriptors.end()) return fail(EBADF);
  return s.handle(it->second, request, arg);
}

void* FakeCamera::mmap(void*, std::size_t length, int, int, int fd, off_t offset) {
  State& s = *state_;
  if (!s.descriptors.count(fd)) {
    errno = EBADF;
    return MAP_FAILED;
  }
  for (auto& b : s.buffers)
    if (off_t(b.offset) == offset && length <= b.length) {
      b.mapped = true;
      return b.memory.get();
    }
  errno = EINVAL;
  return MAP_FAILED;
}

int FakeCamera::munmap(void* address, std::size_t) {
  for (auto& b : state_->buffers)
    if (b.memory.get() == address && b.mapped) {
      b.mapped = false;
      return 0;
    }
  return fail(EINVAL);
}

int FakeCamera::poll(pollfd* fds, nfds_t count, int timeout_ms) {
  State& s = *state_;
  if (count != 1 || !s.descriptors.count(fds[0].fd)) return fail(EINVAL);
  fds[0].revents = s.config.realtime ? s.poll_realtime(timeout_ms) : s.poll_lockstep(timeout_ms);
  return fds[0].revents ? 1 : 0;
}

const FakeCameraStats& FakeCamera::stats() const { return state_->stats; }
const FakeCameraConfig& FakeCamera::config() const { return state_->config; }
bool FakeCamera::streaming() const { return state_->streaming; }
const FakeScene* FakeCamera::scene() const { return dynamic_cast<const FakeScene*>(state_->scene.get()); }
std::size_t FakeCamera::open_descriptors() const { return state_->descriptors.size(); }

std::int32_t FakeCamera::control_value(std::uint32_t id) const {
  for (const auto& c : state_->config.controls)
    if (c.id == id) return c.value;
  return -1;
}

std::size_t FakeCamera::mapped_buffers() const {
  std::size_t n = 0;
  for (const auto& b : state_->buffers) n += b.mapped;
  return n;
}

}  // namespace haptex::capture
