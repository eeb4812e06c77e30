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
#include <opencv2/videoio.hpp>

#include "core/durable_file.hpp"
#include "core/error.hpp"
#include "core/json/schema.hpp"
#include "core/text/format.hpp"
#include "media/codecs.hpp"

namespace haptex::synth {
namespace fs = std::filesystem;
namespace {

constexpr const char* kSchema = "press-sidecar.schema.json";

// The press as an MJPG AVI, OpenCV's own muxer (no timestamps or random IDs: a seed gives the same
// bytes), JPEG quality 95: a tenth of a PNG sequence's size, and what a real sensor sends.
constexpr int kJpegQuality = 95;

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

std::string press_video_path(const std::string& directory, int press) {
  return (fs::path(directory) / (press_name(press) + ".avi")).string();
}

std::string press_sidecar_path(const std::string& directory, int press) {
  return (fs::path(directory) / (press_name(press) + ".json")).string();
}

PressVideoWriter::PressVideoWriter(const std::string& directory, int press, double fps)
    : directory_(directory),
      press_(press),
      fps_(fps),
      partial_video_((fs::path(directory) / (press_name(press) + ".partial.avi")).string()) {
  if (press < 0) throw failure("PressVideoWriter: the press index must be >= 0");
  // The AVI header holds a whole frame rate (OpenCV rounds it), and the sidecar states the same one.
  if (!(fps >= 1) || fps != std::round(fps)) throw failure("PressVideoWriter: the frame rate must be a whole number of frames a second");
  std::error_code ec;
  // Inside an existing folder only: when a signal has taken synth's temporary folder away, a press
  // writer still running must not make it again (core/temporary_name.hpp).
  fs::create_directory(directory, ec);
  if (ec) throw input_error(directory, "", "cannot create the output directory: " + ec.message(), "Choose another -o");
  const std::string sidecar = press_sidecar_path(directory, press);
  check_output_path(sidecar, true);
  sidecar_ = std::make_unique<PartialFile>(sidecar, false);  // locked from here on
  fs::remove(partial_video_, ec);                     // the leftover of a killed run
}

PressVideoWriter::~PressVideoWriter() {
  if (finished_) return;
  video_.reset();
  std::error_code ignored;
  fs::remove(partial_video_, ignored);
}

void PressVideoWriter::add(const cv::Mat& frame) {
  if (finished_) throw failure("PressVideoWriter::add: the press is already finished");
  if (frame.type() != CV_8UC3 || frame.empty()) throw failure("PressVideoWriter::add: frames must be CV_8UC3");
  if (frames_ == 0) {
    size_ = frame.size();
    video_ = media::create_video(partial_video_, cv::CAP_OPENCV_MJPEG, media::fourcc('M', 'J', 'P', 'G'), fps_, size_, true);
    if (!video_) throw failure(partial_video_ + ": OpenCV cannot write an MJPG video here");
    video_->set(cv::VIDEOWRITER_PROP_QUALITY, kJpegQuality);
  }
  if (frame.size() != size_) throw failure("PressVideoWriter::add: every frame of a press must have the same size");
  video_->write(frame);
  ++frames_;
}

PressSidecar PressVideoWriter::finish(PressSidecar sidecar) {
  if (finished_) throw failure("PressVideoWriter::finish: the press is already finished");
  if (sidecar.press != press_) throw failure("PressVideoWriter::finish: the sidecar is for another press");
  if (sidecar.fps != fps_) throw failure("PressVideoWriter::finish: the sidecar's fps is not the video's");
  if (frames_ == 0) throw failure("PressVideoWriter::finish: a press needs at least one frame");
  sidecar.frames = frames_;
  sidecar.width = size_.width;
  sidecar.height = size_.height;
  const std::string sidecar_path = press_sidecar_path(directory_, press_);
  validate(sidecar, sidecar_path);

  const std::string text = to_json(sidecar).dump(2) + "\n";
  write_text(*sidecar_, text);

  // The video on disk before it gets its final name; an older press goes, sidecar first (a folder of
  // PNG frames, as haptex wrote presses until this round, too).
  video_->release();
  // cv::VideoWriter reports no write error: the video read back must hold every frame (a full disk).
  const std::unique_ptr<media::VideoReader> written = media::open_video(partial_video_, cv::CAP_ANY);
  if (const int read_back = written ? int(written->get(cv::CAP_PROP_FRAME_COUNT)) : 0; read_back != frames_)
    throw input_error(partial_video_, "", "the video holds " + std::to_string(read_back) + " of its " + std::to_string(frames_) + " frames",
                      "Check the free space where -o points");
  fsync_path(partial_video_, O_RDONLY);
  const std::string final_video = press_video_path(directory_, press_);
  std::error_code ec;
  fs::remove(sidecar_path, ec);
  fs::remove_all(fs::path(directory_) / press_name(press_), ec);
  fs::rename(partial_video_, final_video, ec);
  if (ec) throw failure(partial_video_ + ": cannot rename to " + final_video + ": " + ec.message());
  fsync_path(directory_, O_RDONLY | O_DIRECTORY);
  finished_ = true;
  try {
    sidecar_->commit();
  } catch (...) {  // a video without its sidecar would be a press of unknown truth
    fs::remove(final_video, ec);
    throw;
  }
  return sidecar;
}

PressSidecar write_press_video(const std::string& directory, const std::vector<cv::Mat>& frames, PressSidecar sidecar) {
  PressVideoWriter writer(directory, sidecar.press, sidecar.fps);
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
