#include "capture/recording/press_recorder.hpp"

#include <linux/videodev2.h>
#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include "capture/device/camera_controls.hpp"
#include "capture/device/fourcc.hpp"
#include "capture/device/usb_bandwidth.hpp"
#include "capture/device/v4l2_device.hpp"
#include "capture/recording/delivered_rate.hpp"
#include "capture/recording/frame_queue.hpp"
#include "capture/recording/session_folder.hpp"
#include "capture/scoring/contact_score.hpp"
#include "core/error.hpp"
#include "core/text/utf8.hpp"
#include "core/naming.hpp"

namespace haptex::capture {
namespace fs = std::filesystem;
namespace {

using Clock = std::chrono::steady_clock;

double cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) + 1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

// The processing thread: pops frames until the queue closes. An exception stops it and is kept for
// the capture thread, which ends the take.
class Worker {
 public:
  Worker(TakeProcessor& processor, FrameQueue<TakeFrame>& queue) : processor_(processor), queue_(queue) {
    thread_ = std::thread([this] { run(); });
  }
  ~Worker() { join(); }
  void join() {
    if (thread_.joinable()) thread_.join();
  }
  bool should_stop() const { return stop_.load(); }
  std::exception_ptr error() const { return error_; }  // read after join()

 private:
  void run() {
    try {
      while (auto frame = queue_.pop()) {
        processor_.process(std::move(*frame));
        if (processor_.enough_presses()) stop_ = true;
      }
    } catch (...) {
      error_ = std::current_exception();
      stop_ = true;
      while (queue_.pop()) {  // let the capture thread finish; the frames are lost with the failed work
      }
    }
  }
  TakeProcessor& processor_;
  FrameQueue<TakeFrame>& queue_;
  std::atomic<bool> stop_{false};
  std::exception_ptr error_;
  std::thread thread_;
};

std::string error_text(std::exception_ptr error) {
  try {
    std::rethrow_exception(error);
  } catch (const std::exception& e) {
    return e.what();
  } catch (...) {
    return "unknown error";
  }
}

// Frames that may wait to be scored: 512 MB of them (a live sensor's second or more), 16 to 1024.
std::size_t queue_capacity(const StreamFormat& format) {
  constexpr double kQueueBytes = 512.0 * 1024 * 1024;
  const double frame_bytes = std::max({double(format.size_image), 2.0 * format.width * format.height, 1.0});
  return std::size_t(std::clamp(kQueueBytes / frame_bytes, 16.0, 1024.0));
}

// The capture thread's loop; returns why the take ended.
std::string capture_loop(V4l2Stream& stream, FrameQueue<TakeFrame>& queue, const Worker& worker,
                         const RecorderOptions& options, const std::atomic<bool>* stop, DeliveredRate& rate) {
  const Clock::time_point start = Clock::now();
  // Time without a frame, counted in poll timeouts (each one waited that long) rather than read
  // from the clock, so a stall means the same to a fake camera whose time is simulated.
  double quiet_seconds = 0;
  std::int64_t index = 0, last_buffer_ns = 0;
  for (;;) {
    const Clock::time_point now = Clock::now();
    if (stop && stop->load()) return "interrupted";
    if (worker.should_stop()) return "presses";
    if (options.seconds > 0 && now - start >= std::chrono::duration<double>(options.seconds)) return "time limit";
    Frame frame;
    switch (stream.next(frame)) {
      case StreamStatus::frame:
        rate.observe(frame.timestamp_ns);
        last_buffer_ns = frame.timestamp_ns;
        queue.push({std::move(frame), index++, stream.stats().error_buffers, stream.stats().poll_timeouts});
        quiet_seconds = 0;
        break;
      case StreamStatus::no_frame:  // the buffer's time passed without a frame; one period when it has none
        quiet_seconds += frame.timestamp_ns > last_buffer_ns && last_buffer_ns > 0 ? double(frame.timestamp_ns - last_buffer_ns) / 1e9
                                                                                 : 1.0 / std::max(stream.format().fps(), 1.0);
        if (frame.timestamp_ns > 0) last_buffer_ns = frame.timestamp_ns;
        if (quiet_seconds >= options.stall_seconds) return "stalled";
        break;
      case StreamStatus::timeout:
        quiet_seconds += stream.poll_timeout_ms() / 1000.0;
        if (quiet_seconds >= options.stall_seconds) return "stalled";
        break;
      case StreamStatus::disconnected: return "disconnected";
      case StreamStatus::ended: return "source ended";  // a replayed file's last frame was taken
    }
  }
}

}  // namespace

void check_recorder_options(const RecorderOptions& o) {
  const auto refuse = [](const std::string& option, const std::string& what, const std::string& fix) {
    throw input_error(option, "", what, fix);
  };
  if (o.material.empty()) refuse("--material", "the material name is empty", "Name the material you press, e.g. --material \"Brick 2\"");
  text::require_utf8(o.material, "--material", "the material name");
  checked_material_id(o.material, "--material", "");  // the session and every press file are stored under that id
  if (o.presses < 1) refuse("--presses", "must be at least 1", "Give the number of presses to record");
  require_reference_frames(o.reference_frames);
  if (o.warmup_frames < 0 || o.pre_frames < 0 || o.post_frames < 0)
    refuse("--warmup/--pre-frames/--post-frames", "must not be negative", "Give 0 or more frames");
  // Frames before a contact wait in memory (a GelSight Mini's are 1 MB each): a bound keeps that sane.
  constexpr int kMostFrames = 1000;
  if (o.warmup_frames > kMostFrames || o.pre_frames > kMostFrames || o.post_frames > kMostFrames)
    refuse("--warmup/--pre-frames/--post-frames", "must be at most " + std::to_string(kMostFrames) + " frames",
           "Give fewer frames (1000 is 40 s at 25 fps)");
  if (o.seconds < 0) refuse("--seconds", "must not be negative", "Give a time limit in seconds, or 0 for none");
  constexpr double kLongestTake = 1e6;  // 11.6 days; a limit far beyond it would overflow the clock's count
  if (o.seconds > kLongestTake) refuse("--seconds", "must be at most 1e6 (11.6 days)", "Give a shorter limit, or 0 for none");
}

RecordingResult record_take(V4l2Stream& stream, const SessionDescription& session, const std::string& output_dir,
                            const RecorderOptions& options, const std::atomic<bool>* stop, const Progress& progress) {
  const double cpu_start = cpu_seconds();
  const Clock::time_point wall_start = Clock::now();
  TakeProcessor processor(session, output_dir, options, progress);
  FrameQueue<TakeFrame> queue(queue_capacity(stream.format()));
  std::string ended_by;
  DeliveredRate rate;
  {
    Worker worker(processor, queue);
    try {
      stream.start();
      ended_by = capture_loop(stream, queue, worker, options, stop, rate);
    } catch (...) {
      stream.stop();
      queue.close();
      worker.join();
      throw;
    }
    stream.stop();
    queue.close();
    worker.join();
    // A file read faster than it is scored ends while its frames still queue: once they are scored,
    // the presses asked for may be there, and that is why the take ended.
    if (ended_by == "source ended" && processor.enough_presses()) ended_by = "presses";
    if (worker.error()) ended_by = "error";
    RecordingResult result;
    result.totals.frames = stream.stats().frames;
    result.totals.dropped_frames = stream.drops().dropped();
    result.totals.error_buffers = stream.stats().error_buffers;
    result.totals.poll_timeouts = stream.stats().poll_timeouts;
    result.totals.max_queue_depth = queue.max_depth();
    result.totals.wall_seconds = std::chrono::duration<double>(Clock::now() - wall_start).count();
    result.totals.cpu_seconds = cpu_seconds() - cpu_start;
    result.totals.delivered_fps = rate.fps();
    result.totals.timestamp_span_seconds = rate.span_seconds();
    if (worker.error()) {
      try {  // best effort: the manifest says what was saved before the failure
        processor.end_of_take("error", result.totals, error_text(worker.error()));
      } catch (...) {
      }
      std::rethrow_exception(worker.error());
    }
    processor.end_of_take(ended_by, result.totals);
    result.session = session;
    result.presses = processor.presses();
    result.totals.corrupt_frames = processor.corrupt_frames();
    result.reference = processor.reference_summary();
    result.ended_by = ended_by;
    result.manifest = processor.manifest_path();
    result.delivery_warning = delivery_warning(session, result.totals);
    return result;
  }
}

RecordingResult record_session(KernelInterface& kernel, const SessionRequest& request, const RecorderOptions& options,
                               const std::atomic<bool>* stop, const Progress& progress, const Warn& warn) {
  check_recorder_options(options);
  check_session_dir(request.output_dir, request.overwrite, request.inputs);  // refused before the device is touched
  V4l2Device device(kernel, request.node);
  const StreamFormat format = negotiate_format(device, request.format);
  if (format.fourcc != V4L2_PIX_FMT_MJPEG && format.fourcc != V4L2_PIX_FMT_YUYV)
    throw input_error(request.node, "pixel format", fourcc_text(format.fourcc) + " frames cannot be recorded",
                      "Choose MJPG (stored as sent) or YUYV (stored as lossless PNG) with --format");
  SessionDescription session;
  session.command = request.command;
  session.material = options.material;
  session.identity = device.identity();
  session.serial = request.serial;
  session.model = request.model;
  session.format = format;
  session.link = request.link;
  session.link_warning = link_warning(device.path(), format, request.link, enumerate_formats(device));
  session.controls = lock_controls(device, request.controls);
  session.warmup_frames = options.warmup_frames;
  session.reference_frames = options.reference_frames;
  session.pre_frames = options.pre_frames;
  session.post_frames = options.post_frames;
  V4l2Stream stream(device, format, request.buffers);
  session.buffers = stream.buffer_count();
  std::error_code ec;
  const bool made_folder = !std::filesystem::exists(std::filesystem::symlink_status(request.output_dir, ec));
  // Only now, so a refused device leaves nothing; an old session comes back unless the take saves a press.
  const PreparedSessionDir prepared = prepare_session_dir(request.output_dir, request.overwrite, request.inputs);
  if (warn && !session.link_warning.empty()) warn(session.link_warning);  // before the user starts pressing
  try {
    return record_take(stream, session, request.output_dir, options, stop, progress);
  } catch (...) {
    // A take that saved nothing (not even its session.json: a full disk) leaves no empty folder it made.
    if (made_folder) std::filesystem::remove(request.output_dir, ec);  // removes only an empty folder
    throw;
  }
}

}  // namespace haptex::capture
