#include "capture/replay/replay_device.hpp"

#include <linux/videodev2.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <sstream>
#include <string_view>

#include "capture/replay/press_file_scene.hpp"
#include "capture/replay/video_scene.hpp"
#include "capture/storage/video_file.hpp"
#include "dataset/press_file.hpp"
#include "core/error.hpp"
#include "core/text/format.hpp"
#include "core/text/utf8.hpp"

namespace haptex::capture {
namespace fs = std::filesystem;
namespace {

constexpr std::string_view kPrefix = "replay:";
const char* const kUsage =
    "Write replay:FILE[,fps=N,lockstep,speed=X,drop=P,error=P,corrupt=P,disconnect=N,stall=FRAME:MS,seed=N]";
constexpr std::array<std::string_view, 9> kKeys = {"fps", "lockstep", "speed", "drop", "error",
                                                   "corrupt", "disconnect", "stall", "seed"};
// The largest frame side replayed, as for the fake camera: above any tactile sensor's frame, and a
// buffer's size stays far from overflow.
constexpr std::uint32_t kMaxSide = 8192;

std::string_view key_of(std::string_view item) { return item.substr(0, item.find('=')); }
bool is_key(std::string_view item) { return std::find(kKeys.begin(), kKeys.end(), key_of(item)) != kKeys.end(); }

// Splits "FILE,KEY=VALUE,..." at the first comma that starts a known key.
std::pair<std::string, std::string> split_file(const std::string& spec) {
  for (std::size_t comma = spec.find(','); comma != std::string::npos; comma = spec.find(',', comma + 1)) {
    const std::size_t next = spec.find(',', comma + 1);
    if (is_key(std::string_view(spec).substr(comma + 1, next == std::string::npos ? std::string::npos : next - comma - 1)))
      return {spec.substr(0, comma), spec.substr(comma + 1)};
  }
  return {spec, ""};
}

// The file must be there and readable; when it is not, but a part of the name before a comma is, the
// rest was meant as keys: name the first unknown one.
void check_file(const std::string& file, const DeviceKeys& keys) {
  std::error_code ec;
  if (!fs::exists(file, ec)) {
    for (std::size_t comma = file.find(','); comma != std::string::npos; comma = file.find(',', comma + 1))
      if (fs::is_regular_file(file.substr(0, comma), ec))
        keys.refuse(std::string(key_of(std::string_view(file).substr(comma + 1, file.find(',', comma + 1) - comma - 1))),
                    "unknown key (after the file " + file.substr(0, comma) + ")");
    throw input_error(file, "", "no such file", "Give the video or press file to replay: replay:FILE[,KEY=VALUE,...]");
  }
  if (fs::is_directory(file, ec))
    throw input_error(file, "", "is a folder", "Give one video or press file to replay (capture extract reads folders)");
  // A pipe would block the recorder in the video's open until someone writes to it.
  if (!fs::is_regular_file(file, ec))
    throw input_error(file, "", "is not a regular file (a device or a pipe)", "Give a video or press file to replay");
  if (::access(file.c_str(), R_OK) != 0)
    throw input_error(file, "", "cannot be read (permission denied)", "Make it readable, or replay a copy");
}

}  // namespace

bool is_replay_device(const std::string& device) { return device.rfind(kPrefix, 0) == 0; }

FakeDevice parse_replay_device(const std::string& device) {
  const DeviceKeys keys(device, kUsage);
  const auto [file, items] = split_file(device.substr(kPrefix.size()));
  if (file.empty()) keys.refuse("FILE", "no file given");
  text::require_utf8(file, "--device replay:", "the file's name");
  check_file(file, keys);

  FakeDevice replay;
  replay.source_file = file;
  FakeCameraConfig& c = replay.config;
  c.realtime = true;
  FakeMode mode = dataset::is_press_file_name(file) ? press_file_replay_mode(file) : video_replay_mode(file);
  for (const auto& [key, value] : keys.items(items)) {
    if (keys.apply_stream_key(c, key, value)) continue;
    if (key != "fps") keys.refuse(key, "unknown key");
    mode.fps = {keys.number(key, value)};
    if (!(mode.fps.front() >= dataset::kLowestFps && mode.fps.front() <= dataset::kHighestFps))
      keys.refuse(key, text::format("expected a rate of %g to %g frames per second", dataset::kLowestFps, dataset::kHighestFps));
  }
  if (!(mode.fps.front() >= dataset::kLowestFps && mode.fps.front() <= dataset::kHighestFps))
    throw input_error(file, "frame rate", text::format("the file does not say its frame rate (or says one outside %g to %g frames per second)", dataset::kLowestFps, dataset::kHighestFps),
                      "Give it: replay:" + file + ",fps=N");
  keys.require_recordable_rate(c, mode.fps.front());
  if (mode.width > kMaxSide || mode.height > kMaxSide)
    throw input_error(file, "frame size", std::to_string(mode.width) + "x" + std::to_string(mode.height) +
                      " is larger than the replay plays (" + std::to_string(kMaxSide) + "x" + std::to_string(kMaxSide) + ")",
                      "Replay a smaller copy");
  if (mode.fourcc == V4L2_PIX_FMT_YUYV && mode.width % 2)
    throw input_error(file, "frame size", "a lossless source is replayed as YUYV, which needs an even width (" +
                      std::to_string(mode.width) + ")", "Re-export it one pixel narrower");
  // MJPG: room for any JPEG of the frame, so no replayed frame arrives cut off (the fake's default
  // w x h holds its own JPEGs, not every file's). YUYV: the frame's size (0, the default).
  if (mode.fourcc == V4L2_PIX_FMT_MJPEG) mode.max_payload = mode.width * mode.height * 3 + 65536;
  c.modes = {mode};
  c.capture_path = std::string(kPrefix) + file;
  c.card = "haptex replay";
  c.driver = "haptex replay";
  c.bus_info = "replay";
  const bool press_file = dataset::is_press_file_name(file);
  const std::string path = file;
  c.film = [press_file, path](const FakeMode& granted) -> std::unique_ptr<CameraScene> {
    if (press_file) return std::make_unique<PressFileScene>(path);
    return std::make_unique<VideoScene>(path, granted.fourcc);
  };
  replay.node = c.capture_path;
  replay.inter_frame = !press_file && probe_video_file(file).inter_frame;
  return replay;
}

}  // namespace haptex::capture
