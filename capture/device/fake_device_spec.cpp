#include "capture/device/fake_device_spec.hpp"

#include <linux/videodev2.h>

#include <cfloat>
#include <optional>
#include <sstream>

#include "capture/device/fourcc.hpp"
#include "core/error.hpp"
#include "core/text/format.hpp"
#include "core/text/parse_number.hpp"
#include "dataset/press_file.hpp"

namespace haptex::capture {
namespace {

constexpr double kSlowest = 0.01, kFastest = 100;  // speed=X, times the rate

const char* const kFakeUsage =
    "Write fake:size=WxH,format=MJPG,fps=N,presses=N,drop=P,error=P,corrupt=P,disconnect=N,"
    "stall=FRAME:MS,speed=X,lockstep,seed=N,metadata";

void apply(FakeDevice& fake, FakeMode& mode, bool& fps_given, const DeviceKeys& keys, const std::string& key,
           const std::string& value) {
  FakeCameraConfig& c = fake.config;
  if (keys.apply_stream_key(c, key, value)) return;
  if (key == "size") {
    const std::optional<text::FrameSize> size = text::parse_frame_size(value);
    if (!size) keys.refuse(key, "'" + value + "' is not WIDTHxHEIGHT in plain decimals (no sign, no leading zero, no space)");
    const double width = double(size->width), height = double(size->height);
    // 4096: above any tactile sensor's frame (a GelSight Mini's is 3280 x 2464), and the float images
    // the fake renders its frames from stay under 1 GB (review 5: 8192x8192 took minutes to start).
    if (width > 4096 || height > 4096) keys.refuse(key, "the fake camera makes frames of at most 4096x4096");
    mode.width = std::uint32_t(width);
    mode.height = std::uint32_t(height);
    if (mode.width < 16 || mode.height < 16 || mode.width % 2) keys.refuse(key, "expected an even width and a size of at least 16x16");
  } else if (key == "format") {
    mode.fourcc = fourcc_code(value, "--device " + keys.device());
    if (mode.fourcc != V4L2_PIX_FMT_MJPEG && mode.fourcc != V4L2_PIX_FMT_YUYV) keys.refuse(key, "the fake sends MJPG or YUYV");
  } else if (key == "fps") {
    mode.fps = {keys.number(key, value)};
    fps_given = true;
  } else if (key == "presses") {
    c.scene.presses = value == "-1" ? -1 : int(keys.count(key, value));
  } else if (key == "metadata") {
    keys.flag(key, value);
    fake.node = c.metadata_path;
  } else {
    keys.refuse(key, "unknown key");
  }
}

}  // namespace

void DeviceKeys::refuse(const std::string& key, const std::string& what) const {
  throw input_error("--device " + device_, key, what, usage_);
}

std::vector<std::pair<std::string, std::string>> DeviceKeys::items(const std::string& list) const {
  std::vector<std::pair<std::string, std::string>> out;
  std::stringstream in(list);
  std::string item;
  while (std::getline(in, item, ',')) {
    if (item.empty()) continue;
    const auto eq = item.find('=');
    const std::string key = item.substr(0, eq);
    for (const auto& [seen, value] : out)
      if (seen == key && key != "stall") refuse(key, "given twice");
    out.emplace_back(key, eq == std::string::npos ? "" : item.substr(eq + 1));
  }
  return out;
}

double DeviceKeys::number(const std::string& key, const std::string& text) const {
  // Plain decimal only ("0x1e" is no rate, "025" no 25), at most 1e12: frame counts and rates are cast to integers, and
  // no take runs that long. No subnormal: README, "numbers ... that a 32-bit float holds".
  const std::optional<double> value = text::parse_number(text);
  if (value && text::is_plain_decimal(text, text::Decimal::real) && (*value == 0 || *value >= FLT_MIN) && *value <= 1e12) return *value;
  refuse(key, "'" + text + "' is not a number from 0 to 1e12 in plain decimals (0 or at least 1.2e-38; no leading zeros)");
}

std::uint64_t DeviceKeys::count(const std::string& key, const std::string& text) const {
  // Review 8: disconnect=1.5 was cut to 1 frame and seed=0.5 to 0, where --seed 0.5 is refused.
  if (!text::is_plain_decimal(text, text::Decimal::natural) || number(key, text) > 1e12)
    refuse(key, "'" + text + "' is not a whole number from 0 to 1e12 in plain decimals (no fraction, exponent or leading zeros)");
  return std::uint64_t(number(key, text));
}

void DeviceKeys::flag(const std::string& key, const std::string& value) const {
  if (!value.empty()) refuse(key, "is a flag and takes no value (give '" + key + "' alone)");
}

double DeviceKeys::percent(const std::string& key, const std::string& text) const {
  const double value = number(key, text);
  if (value > 100) refuse(key, "'" + text + "' is not a percentage from 0 to 100");
  return value;
}

bool DeviceKeys::apply_stream_key(FakeCameraConfig& c, const std::string& key, const std::string& value) const {
  if (key == "drop") {
    c.drop_percent = percent(key, value);
  } else if (key == "error") {
    c.error_percent = percent(key, value);
  } else if (key == "corrupt") {
    c.corrupt_percent = percent(key, value);
  } else if (key == "disconnect") {
    c.disconnect_after = count(key, value);
  } else if (key == "stall") {
    const auto colon = value.find(':');
    if (colon == std::string::npos) refuse(key, "expected FRAME:MILLISECONDS");
    const std::uint64_t ms = count(key, value.substr(colon + 1));
    if (ms > 3600000) refuse(key, "a stall of more than an hour (" + value.substr(colon + 1) + " ms)");
    c.stalls.push_back({count(key, value.substr(0, colon)), int(ms)});
  } else if (key == "speed") {
    // Bounded so a frame's wall-clock due time stays a number of nanoseconds an int64 holds and the
    // device's clock never stands still (review 4: speed=1e-30 spun without end).
    c.speed = number(key, value);
    if (!(c.speed >= kSlowest && c.speed <= kFastest)) refuse(key, "'" + value + "' is not from 0.01 to 100 (times the rate)");
  } else if (key == "lockstep") {
    flag(key, value);
    c.realtime = false;
  } else if (key == "seed") {
    c.seed = count(key, value);
  } else {
    return false;
  }
  return true;
}

void DeviceKeys::require_recordable_rate(const FakeCameraConfig& config, double fps) const {
  if (config.realtime && fps * config.speed < dataset::kLowestFps)
    refuse("speed", text::format("fps %g at speed %g sends %g frames a second, fewer than the %g a recording takes at the least", fps,
                                 config.speed, fps * config.speed, dataset::kLowestFps));
}

bool is_fake_device(const std::string& device) { return device == "fake" || device.rfind("fake:", 0) == 0; }

FakeDevice parse_fake_device(const std::string& device) {
  const DeviceKeys keys(device, kFakeUsage);
  FakeDevice fake;
  fake.config.realtime = true;
  fake.node = fake.config.capture_path;
  FakeMode mode = gelsight_mini_mode();
  bool fps_given = false;
  if (device.size() > 5) {
    for (const auto& [key, value] : keys.items(device.substr(5))) apply(fake, mode, fps_given, keys, key, value);
  }
  if (!fps_given && (mode.width != 3280 || mode.height != 2464)) mode.fps = {30.0};
  if (!(mode.fps.front() >= dataset::kLowestFps && mode.fps.front() <= dataset::kHighestFps))
    keys.refuse("fps", "must be from 1 to 1000 frames per second, as a press file's own fps must be");
  keys.require_recordable_rate(fake.config, mode.fps.front());
  fake.config.modes = {mode};
  // Messages and session.json name the device as the user gave it, not the node the fake emulates:
  // a real camera may well be /dev/video0 (review 8, #11).
  (fake.node == fake.config.metadata_path ? fake.config.metadata_path : fake.config.capture_path) = device;
  fake.node = device;
  return fake;
}

}  // namespace haptex::capture
