#include "synth/press_video_writer.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <utility>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "core/durable_file.hpp"
#include "core/error.hpp"
#include "core/json/schema.hpp"
#include "core/text/format.hpp"

namespace haptex::synth {
namespace fs = std::filesystem;
namespace {

constexpr const char* kSchema = "press-sidecar.schema.json";

std::string frame_name(int index) {
  return text::format("frame_%04d.png", index);
}

// OpenCV's default PNG settings are its fast path (SUB filter, zlib level 1); Huffman-only coding
// is faster still and smaller on sensor noise, which LZ77 matching cannot exploit. Setting
// IMWRITE_PNG_COMPRESSION instead would switch libpng to trying every filter: twice as slow.
std::vector<unsigned char> encode_png(const cv::Mat& frame) {
  std::vector<unsigned char> png;
  if (!cv::imencode(".png", frame, png, {cv::IMWRITE_PNG_STRATEGY, cv::IMWRITE_PNG_STRATEGY_HUFFMAN_ONLY}))
    throw failure("cannot encode a press frame as PNG");
  return png;
}

void write_file(const std::string& path, const void* data, std::size_t size) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw failure(path + ": cannot create: " + std::strerror(errno));
  const auto* bytes = static_cast<const char*>(data);
  std::size_t done = 0;
  while (done < size) {
    const ssize_t n = ::write(fd, bytes + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int saved = errno;
      ::close(fd);
      throw failure(path + ": write failed (disk full?): " + std::strerror(saved));
    }
    done += std::size_t(n);
  }
  if (::close(fd) != 0) throw failure(path + ": write failed: " + std::strerror(errno));
}

double rounded(double value, double step) { return std::round(value / step) * step; }

nlohmann::ordered_json to_json(const PressSidecar& s) {
  nlohmann::ordered_json doc = {{"material", s.material},     {"press", s.press},
                                {"fps", s.fps},               {"frames", s.frames},
                                {"width", s.width},           {"height", s.height},
                                {"peak_frame", s.peak_frame}, {"contact_first", s.contact_first},
                                {"contact_last", s.contact_last}};
  doc["peak_depth_mm"] = rounded(s.peak_depth_mm, 1e-6);
  if (s.location_mm) doc["location_mm"] = {rounded((*s.location_mm)[0], 1e-4), rounded((*s.location_mm)[1], 1e-4)};
  if (s.crop_px) doc["crop_px"] = *s.crop_px;
  doc["source"] = s.source;
  return doc;
}

// What the schema cannot say: the frame indices lie inside the video and in order.
void check_indices(const PressSidecar& s, const std::string& path) {
  if (!(0 <= s.contact_first && s.contact_first <= s.peak_frame && s.peak_frame <= s.contact_last &&
        s.contact_last < s.frames))
    throw input_error(path, "/peak_frame", "needs contact_first <= peak_frame <= contact_last < frames",
                      "Fix the frame indices");
}

void validate(const PressSidecar& s, const std::string& path) {
  json::validate(nlohmann::json::parse(to_json(s).dump()), kSchema, path);
  check_indices(s, path);
}

}  // namespace

std::string press_name(int press) { return "press_" + std::to_string(press); }

std::string press_frame_pattern(const std::string& directory, int press) {
  return (fs::path(directory) / press_name(press) / "frame_%04d.png").string();
}

std::string press_sidecar_path(const std::string& directory, int press) {
  return (fs::path(directory) / (press_name(press) + ".json")).string();
}

PressVideoWriter::PressVideoWriter(const std::string& directory, int press)
    : directory_(directory), press_(press), partial_dir_((fs::path(directory) / (press_name(press) + ".partial")).string()) {
  if (press < 0) throw failure("PressVideoWriter: the press index must be >= 0");
  std::error_code ec;
  fs::create_directories(directory, ec);
  if (ec) throw input_error(directory, "", "cannot create the output directory: " + ec.message(), "Choose another -o");
  const std::string sidecar = press_sidecar_path(directory, press);
  check_output_path(sidecar, true);
  sidecar_ = std::make_unique<PartialFile>(sidecar);  // locked from here on
  fs::remove_all(partial_dir_, ec);                   // the leftovers of a killed run
  if (!fs::create_directory(partial_dir_, ec))
    throw input_error(partial_dir_, "", "cannot create the frame directory: " + ec.message(), "Choose another -o");
}

PressVideoWriter::~PressVideoWriter() {
  if (finished_) return;
  std::error_code ignored;
  fs::remove_all(partial_dir_, ignored);
}

void PressVideoWriter::add(const cv::Mat& frame) {
  if (finished_) throw failure("PressVideoWriter::add: the press is already finished");
  if (frame.type() != CV_8UC3 || frame.empty()) throw failure("PressVideoWriter::add: frames must be CV_8UC3");
  if (frames_ == 0) size_ = frame.size();
  if (frame.size() != size_) throw failure("PressVideoWriter::add: every frame of a press must have the same size");
  const std::vector<unsigned char> png = encode_png(frame);
  write_file((fs::path(partial_dir_) / frame_name(frames_)).string(), png.data(), png.size());
  ++frames_;
}

PressSidecar PressVideoWriter::finish(PressSidecar sidecar) {
  if (finished_) throw failure("PressVideoWriter::finish: the press is already finished");
  if (sidecar.press != press_) throw failure("PressVideoWriter::finish: the sidecar is for another press");
  sidecar.frames = frames_;
  sidecar.width = size_.width;
  sidecar.height = size_.height;
  const std::string sidecar_path = press_sidecar_path(directory_, press_);
  validate(sidecar, sidecar_path);

  const std::string text = to_json(sidecar).dump(2) + "\n";
  write_file(sidecar_->path(), text.data(), text.size());

  // Frames on disk before the directory gets its final name; an older press goes, sidecar first.
  for (int i = 0; i < frames_; ++i) fsync_path((fs::path(partial_dir_) / frame_name(i)).string(), O_RDONLY);
  fsync_path(partial_dir_, O_RDONLY | O_DIRECTORY);
  const std::string final_dir = (fs::path(directory_) / press_name(press_)).string();
  std::error_code ec;
  fs::remove(sidecar_path, ec);
  fs::remove_all(final_dir, ec);
  fs::rename(partial_dir_, final_dir, ec);
  if (ec) throw failure(partial_dir_ + ": cannot rename to " + final_dir + ": " + ec.message());
  finished_ = true;
  try {
    sidecar_->commit();
  } catch (...) {  // frames without their sidecar would be a press of unknown truth
    fs::remove_all(final_dir, ec);
    throw;
  }
  return sidecar;
}

PressSidecar write_press_video(const std::string& directory, const std::vector<cv::Mat>& frames, PressSidecar sidecar) {
  PressVideoWriter writer(directory, sidecar.press);
  for (const cv::Mat& frame : frames) writer.add(frame);
  return writer.finish(std::move(sidecar));
}

PressSidecar read_press_sidecar(const std::string& path) {
  const nlohmann::json doc = json::read_file(path);
  json::validate(doc, kSchema, path);
  PressSidecar s;
  s.material = doc.at("material").get<std::string>();
  s.press = doc.at("press").get<int>();
  s.fps = doc.at("fps").get<double>();
  s.frames = doc.at("frames").get<int>();
  s.width = doc.at("width").get<int>();
  s.height = doc.at("height").get<int>();
  s.peak_frame = doc.at("peak_frame").get<int>();
  s.contact_first = doc.at("contact_first").get<int>();
  s.contact_last = doc.at("contact_last").get<int>();
  s.peak_depth_mm = doc.at("peak_depth_mm").get<double>();
  if (doc.contains("location_mm")) s.location_mm = doc.at("location_mm").get<std::array<double, 2>>();
  if (doc.contains("crop_px")) s.crop_px = doc.at("crop_px").get<std::array<int, 4>>();
  s.source = doc.at("source").get<std::string>();
  check_indices(s, path);
  return s;
}

}  // namespace haptex::synth
