#include "capture/storage/video_file.hpp"

#include <cstdlib>
#include <mutex>

#include "capture/storage/avi_frame_rate.hpp"
#include "core/error.hpp"
#include "core/open_files.hpp"
#include "media/codecs.hpp"

namespace haptex::capture {

void prepare_video_environment() {
  static std::once_flag once;
  std::call_once(once, [] {
    // FFmpeg logs decoding problems of damaged videos straight to stderr; libraries here never print
    // (damage shows as frames that do not decode). OpenCV reads this once, when FFmpeg is first used;
    // a user's own setting wins.
    setenv("OPENCV_FFMPEG_LOGLEVEL", "-8", 0);  // AV_LOG_QUIET
    // A packet cut short (a truncated file) would decode, concealed, into a frame whose missing part
    // differs from the reference and so scores as the strongest contact: FFmpeg's demuxer drops such
    // packets instead (read per open).
    setenv("OPENCV_FFMPEG_CAPTURE_OPTIONS", "fflags;discardcorrupt", 0);
  });
}

std::unique_ptr<media::VideoReader> open_video_file(const std::string& path) {
  prepare_video_environment();
  // FFmpeg only: other backends (GStreamer) print their own warnings on failure, and libraries
  // here never print.
  std::unique_ptr<media::VideoReader> video = media::open_video(path, cv::CAP_FFMPEG);
  if (!video) {
    error_opening(path);  // out of descriptors, FFmpeg fails for the machine's limit, not the file's
    throw input_error(path, "", "OpenCV cannot open this as a video",
                      "Give a video file (.avi, .mkv, .mp4 ...) or a press file (.h5) from 'haptex capture record'");
  }
  return video;
}

VideoProbe probe_video_file(const std::string& path) {
  const std::unique_ptr<media::VideoReader> video = open_video_file(path);
  cv::Mat first;
  if (!video->read(first) || first.empty())
    throw input_error(path, "frame 0", "the video has no readable frame",
                      "Check it plays (ffprobe " + path + "); re-export it as FFV1 .mkv or MJPG .avi");
  VideoProbe probe;
  probe.size = first.size();
  // An AVI that states no rate is reported at FFmpeg's guess of 25 fps: its own headers decide.
  const double fps = avi_frame_rate(path).value_or(video->get(cv::CAP_PROP_FPS));
  probe.fps = fps > 0 && fps < 1000 ? fps : 0.0;
  const auto fourcc = std::uint32_t(video->get(cv::CAP_PROP_FOURCC));
  probe.lossless = fourcc == 0;  // raw frames
  for (const char* codec : {"FFV1", "FFVH", "HFYU", "png ", "MPNG", "UYVY", "YUY2", "I420", "Y800", "RGBA", "BGRA"})
    if (fourcc == std::uint32_t(media::fourcc(codec[0], codec[1], codec[2], codec[3]))) probe.lossless = true;
  probe.inter_frame = !probe.lossless;
  for (const char* codec : {"MJPG", "mjpg", "AVRn", "dmb1", "jpeg"})
    if (fourcc == std::uint32_t(media::fourcc(codec[0], codec[1], codec[2], codec[3]))) probe.inter_frame = false;
  // Raw reading only for plain MJPG: AVRn and dmb1 may hold two interlaced fields per packet.
  for (const char* codec : {"MJPG", "mjpg"})
    if (fourcc == std::uint32_t(media::fourcc(codec[0], codec[1], codec[2], codec[3]))) probe.mjpeg = true;
  return probe;
}

}  // namespace haptex::capture
