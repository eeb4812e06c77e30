#pragma once
// Video files through OpenCV's FFmpeg backend, opened the way every haptex reader needs them: quietly
// (libraries never print), with packets cut short dropped (a copy that stopped early would otherwise
// end in a concealed, half-grey frame that scores as the strongest contact), and with the codecs that
// keep frames exactly told apart. Extraction reads videos through it, and so does replay.
#include <cstdint>
#include <memory>
#include <string>

#include <opencv2/core.hpp>
#include <opencv2/videoio.hpp>

#include "media/codecs.hpp"

namespace haptex::capture {

// Sets the environment OpenCV's FFmpeg backend reads (quiet, corrupt packets dropped), once; call it
// before threads start (setenv races with other threads' getenv). open_video_file calls it too.
void prepare_video_environment();
// Throws haptex::Error (bad_input) naming the file when OpenCV cannot open it as a video.
std::unique_ptr<media::VideoReader> open_video_file(const std::string& path);

struct VideoProbe {
  cv::Size size;       // of the first frame
  double fps = 0;      // 0 when the container does not say (or says something absurd)
  bool lossless = false;  // FFV1, HuffYUV, PNG or uncompressed: frames as they were made
  // Lossy with prediction between frames (MPEG-4, H.264 ...): its no-contact frames copy each other's
  // compression noise, unlike MJPG's, whose frames are each compressed alone.
  bool inter_frame = false;
  bool mjpeg = false;  // MJPG, each frame one JPEG: read raw, the frames' bytes can be kept as they are
};
// Opens the video and reads its first frame. Throws haptex::Error (bad_input) naming the file when
// it does not open or has no readable frame.
VideoProbe probe_video_file(const std::string& path);

}  // namespace haptex::capture
