// haptex capture record (--device NODE | --serial S) --material NAME [--presses 5] -o DIR
// One take from a sensor into one press file per press and a session manifest. Ctrl-C ends the take
// cleanly: the press being recorded is closed with every frame taken.
#include <climits>
#include <csignal>
#include <optional>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>

#include "apps/output_options.hpp"
#include "apps/stop_on_signal.hpp"
#include "apps/capture_subcommands.hpp"
#include "apps/terminal_progress.hpp"
#include "capture/device/camera_controls.hpp"
#include "capture/device/fake_device_spec.hpp"
#include "capture/device/fourcc.hpp"
#include "capture/device/sensor_discovery.hpp"
#include "capture/device/system_kernel.hpp"
#include "capture/recording/press_recorder.hpp"
#include "capture/replay/replay_device.hpp"
#include "apps/number_checks.hpp"
#include "core/text/parse_number.hpp"
#include "core/error.hpp"
#include "core/text/shell_quote.hpp"
#include "core/text/utf8.hpp"

namespace haptex::apps {
namespace {

class CaptureRecord : public CaptureSubcommand {
 public:
  CLI::App* declare(CLI::App& capture) override {
    CLI::App* app = capture.add_subcommand("record", "Record presses from a sensor: one press file per press");
    auto* device = app->add_option("--device", device_, "Capture node (/dev/videoN), fake[:KEY=VALUE,...] for the fake camera, or replay:FILE[,KEY=VALUE,...] to play a video or press file as a sensor");
    auto* serial = app->add_option("--serial", serial_, "Serial number of a sensor 'haptex capture devices' lists");
    device->excludes(serial);
    serial->excludes(device);
    app->add_option("--material", options_.material, "Name of the material pressed (e.g. \"Brick 2\")")->required();
    app->add_option("--presses", options_.presses, "Presses to record before the take ends")->capture_default_str();
    add_output_options(*app, request_.output_dir, request_.overwrite, "Session folder for the press files and session.json");
    app->add_option("--format", format_, "Pixel format (default: MJPG when offered)");
    app->add_option("--size", size_, "Frame size WIDTHxHEIGHT (default: the largest)");
    app->add_option("--fps", fps_, "Frame rate (default: the highest at that size)")->check(positive_number());
    app->add_option("--control", controls_, "NAME=VALUE for a V4L2 control (old or new kernel names), e.g. exposure_time_absolute=150")
        ->take_all();
    app->add_option("--seconds", options_.seconds, "End the take after this long (0: no limit)")->capture_default_str();
    warmup_ = app->add_option("--warmup", options_.warmup_frames,
                              "Frames discarded after stream start (a sensor's black and settling frames; default 10, "
                              "0 with --device replay:, which starts with the file's first frame)");
    app->add_option("--reference-frames", options_.reference_frames, "No-contact frames averaged into the reference (10 to 250)")
        ->capture_default_str();
    app->add_option("--pre-frames", options_.pre_frames, "Frames kept before each contact")->capture_default_str();
    app->add_option("--post-frames", options_.post_frames, "Frames kept after each release")->capture_default_str();
    app->add_option("--buffers", request_.buffers, "Driver buffers, 4 to 8")->capture_default_str()->check(CLI::Range(4, 8));
    // Read only to find --serial's sensor: without --serial a list given would be ignored unread.
    app->add_option("--sensors", sensors_, "JSON list of more sensors for --serial (the form of schemas/tactile-sensors.json)")
        ->needs(serial);
    return app;
  }

  bool ends_on_signals_itself() const override { return true; }  // StopOnSignal

  int run(const GlobalOptions& global) override {
    if (device_.empty() && serial_.empty())
      throw input_error("capture record", "", "no sensor given", "Name it with --device /dev/videoN or --serial S");
    text::require_utf8(options_.material, "--material", "the material name");
    // A replayed file holds no stream start-up: its first frame is the take's first (docs/capture.md, "Replay").
    if (capture::is_replay_device(device_) && warmup_->count() == 0) options_.warmup_frames = 0;
    build_request(global);
    StopOnSignal stop_on_signal;
    const capture::RecordingResult result = record(global);
    print(result, global);
    if (!result.delivery_warning.empty() && !global.quiet)
      std::cerr << "haptex capture: warning: " << result.delivery_warning << "\n";
    if (!result.device_fault()) return 0;
    std::cerr << "haptex capture: error: " << request_.node << ": the sensor "
              << (result.ended_by == "disconnected" ? "was disconnected" : "stopped sending frames") << " after "
              << result.totals.frames << " frames; " << result.presses.size() << " presses saved in "
              << request_.output_dir << ". Check the cable and record the missing presses into a new folder\n";
    return 1;
  }

 private:
  capture::RecordingResult record(const GlobalOptions& global) {
    const Progress progress = terminal_progress(global, "record");
    // Before the take, so the user can stop and fix it before pressing (also in --json's warnings).
    const capture::Warn warn = [&global](const std::string& warning) {
      if (!global.quiet) std::cerr << "haptex capture: warning: " << warning << "\n";
    };
    if (capture::is_fake_device(device_) || capture::is_replay_device(device_)) {
      const capture::FakeDevice fake =
          capture::is_fake_device(device_) ? capture::parse_fake_device(device_) : capture::parse_replay_device(device_);
      capture::FakeCamera camera(fake.config);
      request_.node = fake.node;
      if (!fake.source_file.empty()) request_.inputs = {fake.source_file};
      if (fake.inter_frame) {
        const auto& modes = fake.config.modes;
        options_.calibration_frames = capture::calibration_frames(modes.empty() || modes.front().fps.empty() ? 0 : modes.front().fps.front());
      }
      return capture::record_session(camera, request_, options_, &StopOnSignal::stop_requested(), progress, warn);
    }
    capture::SystemKernel kernel;
    return capture::record_session(kernel, request_, options_, &StopOnSignal::stop_requested(), progress, warn);
  }

  void build_request(const GlobalOptions& global) {
    // Every option given (apps/provenance.hpp), and the folder: pasted into a shell, it records such a take again.
    request_.command = global.command_line + " -o " + text::shell_quoted(request_.output_dir);
    if (!serial_.empty()) {
      capture::SensorCatalog catalog = capture::SensorCatalog::builtin();
      if (!sensors_.empty()) catalog.prepend(capture::SensorCatalog::from_file(sensors_));
      const auto sensor = capture::find_sensor_by_serial(capture::discover_sensors(capture::list_usb_devices(), catalog), serial_);
      request_.node = sensor.capture_node;
      request_.serial = sensor.serial;
      request_.model = sensor.model;
      request_.link = sensor.link;
    } else {
      request_.node = device_;
      // The fake camera has no USB link; a real node's is found through sysfs (unknown if it is not USB).
      if (!capture::is_fake_device(device_)) request_.link = capture::usb_link_of_node("/sys", device_);
    }
    if (!format_.empty()) request_.format.fourcc = capture::fourcc_code(format_, "--format");
    if (!size_.empty()) parse_size();
    if (fps_ > 0) request_.format.fps = fps_;
    for (const auto& c : controls_) {
      const auto eq = c.find('=');
      if (eq == std::string::npos)
        throw input_error("--control " + c, "", "expected NAME=VALUE", "e.g. --control exposure_time_absolute=150");
      const std::optional<long long> value = text::parse_whole_number(c.substr(eq + 1));
      // V4L2 integer controls are 32-bit: a larger value would be cut to another one.
      if (!value || *value < INT32_MIN || *value > INT32_MAX)
        throw input_error("--control " + c, "", "the value is not a whole decimal number of 32 bits", "e.g. --control gain=10");
      const std::uint32_t id = capture::control_id(c.substr(0, eq));
      if (request_.controls.count(id))
        throw input_error("--control " + c, "", "the control is given twice", "Give each control once");
      request_.controls[id] = *value;
    }
  }

  void parse_size() {
    const std::optional<text::FrameSize> size = text::parse_frame_size(size_);
    constexpr long long kLargestSide = 65535;  // V4L2 and every sensor haptex knows stay far below
    if (!size || size->width > kLargestSide || size->height > kLargestSide)
      throw input_error("--size " + size_, "", "expected WIDTHxHEIGHT, two whole numbers from 1 to 65535", "e.g. --size 3280x2464");
    request_.format.width = std::uint32_t(size->width);
    request_.format.height = std::uint32_t(size->height);
  }

  void print(const capture::RecordingResult& r, const GlobalOptions& global) const {
    const double cpu_percent = r.totals.wall_seconds > 0 ? 100 * r.totals.cpu_seconds / r.totals.wall_seconds : 0;
    if (global.json) {
      std::cout << capture::session_manifest(r.session, r.reference, r.presses, r.totals, r.ended_by).dump(2) << "\n";
      return;
    }
    if (global.quiet) return;
    if (global.verbose)
      for (const auto& p : r.presses)
        std::cerr << p.file << ": take frames " << p.take_first_frame << "-" << p.take_last_frame << ", contact "
                  << p.contact_first << "-" << p.contact_last << ", peak " << p.peak_frame << ", " << p.dropped_frames
                  << " dropped, ended by " << p.ended_by << "\n";
    std::cout << "recorded " << r.presses.size() << " presses of " << text::printable(options_.material) << " into " << text::printable(request_.output_dir)
              << " (" << r.ended_by << "): " << r.totals.frames << " frames, " << r.totals.dropped_frames << " dropped, "
              << r.totals.error_buffers << " error buffers; " << capture::fourcc_text(r.session.format.fourcc) << " "
              << r.session.format.width << "x" << r.session.format.height << " at " << r.session.format.fps() << " fps";
    if (r.totals.delivered_fps) std::cout << " (" << std::fixed << std::setprecision(1) << *r.totals.delivered_fps << " delivered)";
    std::cout << "; CPU " << std::fixed << std::setprecision(0) << cpu_percent << "% of one core\n";
  }

  std::string device_, serial_, format_, size_, sensors_;
  double fps_ = 0;
  std::vector<std::string> controls_;
  CLI::Option* warmup_ = nullptr;
  capture::SessionRequest request_;
  capture::RecorderOptions options_;
};

}  // namespace

std::unique_ptr<CaptureSubcommand> make_capture_record() { return std::make_unique<CaptureRecord>(); }

}  // namespace haptex::apps
