#pragma once
// One press video on disk, as a GelSight sensor sends it: DIR/press_<j>.avi, MJPG in an AVI written by
// OpenCV's own muxer (JPEG quality 95), plus the sidecar DIR/press_<j>.json
// (schemas/press-sidecar.schema.json) with the press's ground truth. OpenCV's muxer writes no date or
// random ID (Matroska's does), so a seed gives byte-identical files. Writes are atomic: the video goes
// to press_<j>.partial.avi, renamed when complete; the sidecar comes last, so its presence means the
// video is whole.
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/videoio.hpp>

#include "media/codecs.hpp"

namespace haptex {
class PartialFile;
}

namespace haptex::synth {

struct PressSidecar {
  std::string material;
  int press = 0;
  double fps = 30;
  int frames = 0, width = 0, height = 0;  // filled in by the writer from the frames it wrote
  int peak_frame = 0;                     // the single frame of deepest contact
  int contact_first = 0, contact_last = 0;
  double peak_depth_mm = 0;
  std::optional<std::array<double, 2>> location_mm;  // rendered presses: the image's corner in the surface
  std::optional<std::array<int, 4>> crop_px;         // photograph presses: x, y, width, height of the crop
  std::string source;                                // the command line that made it
};

std::string press_name(int press);                                       // "press_3"
std::string press_video_path(const std::string& directory, int press);  // DIR/press_<j>.avi
std::string press_sidecar_path(const std::string& directory, int press);

class PressVideoWriter {
 public:
  // Starts press_<j> in `directory` (created if missing) at `fps` frames a second. Throws
  // haptex::Error (bad_input) when the directory cannot be written or another haptex run is writing
  // this press.
  PressVideoWriter(const std::string& directory, int press, double fps);
  ~PressVideoWriter();  // an unfinished press leaves nothing behind
  PressVideoWriter(const PressVideoWriter&) = delete;
  PressVideoWriter& operator=(const PressVideoWriter&) = delete;

  // Appends a frame: CV_8UC3 (OpenCV's BGR order), every frame the same size.
  void add(const cv::Mat& frame);
  // Completes the press: sidecar.press and sidecar.fps must be this press's; frames, width and height
  // are filled in. The sidecar is checked (schema, and contact_first <= peak_frame <= contact_last <
  // frames), the video replaces any older press_<j>, then the sidecar is written. Returns what was written.
  PressSidecar finish(PressSidecar sidecar);

 private:
  std::string directory_;
  int press_;
  double fps_;
  std::unique_ptr<PartialFile> sidecar_;  // press_<j>.json.partial: also the lock against a second run
  std::string partial_video_;             // press_<j>.partial.avi
  std::unique_ptr<media::VideoWriter> video_;
  int frames_ = 0;
  cv::Size size_;
  bool finished_ = false;
};

// The whole press at once.
PressSidecar write_press_video(const std::string& directory, const std::vector<cv::Mat>& frames, PressSidecar sidecar);

// Reads and checks a sidecar (schema and frame-index consistency); throws haptex::Error (bad_input).
PressSidecar read_press_sidecar(const std::string& path);

}  // namespace haptex::synth
