#pragma once
// Images and videos encoded, decoded and read through OpenCV's imgcodecs and videoio, which live in a
// plugin (libhaptex_opencv_codecs.so, plugins/opencv_codecs.cpp) loaded the first time one is needed.
// Those two libraries bring in some 200 others (FFmpeg, GStreamer, GDAL, ...) whose loading took most
// of every command's start-up, also of the many that never touch a video (docs/architecture.md,
// "Start-up"). The plugin is found next to the binary (build tree), in lib/haptex beside it (installed)
// or through the RUNPATH a program linking haptex::media gets (docs/library.md).
#include <memory>
#include <string>
#include <vector>

#include <opencv2/core.hpp>
// The flags are OpenCV's own (cv::IMREAD_COLOR, cv::IMWRITE_JPEG_QUALITY, cv::CAP_FFMPEG, ...): these
// headers' constants only; calling their functions outside the plugin fails to link.
#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>

namespace haptex::media {

// A video being read (cv::VideoCapture's calls, as haptex uses them).
class VideoReader {
 public:
  virtual ~VideoReader() = default;
  virtual bool read(cv::Mat& frame) = 0;
  virtual bool grab() = 0;
  virtual bool retrieve(cv::Mat& frame) = 0;
  virtual double get(int property) const = 0;
  virtual bool set(int property, double value) = 0;
};

// A video being written (cv::VideoWriter's calls, as haptex uses them).
class VideoWriter {
 public:
  virtual ~VideoWriter() = default;
  virtual bool set(int property, double value) = 0;
  virtual void write(const cv::Mat& frame) = 0;
  virtual void release() = 0;
};

// cv::imencode, cv::imdecode and cv::imread.
bool encode_image(const std::string& extension, const cv::Mat& image, std::vector<unsigned char>& bytes,
                  const std::vector<int>& parameters = {});
cv::Mat decode_image(cv::InputArray bytes, int flags);
cv::Mat read_image(const std::string& path, int flags);

// The video opened with OpenCV backend `api` (cv::CAP_FFMPEG ...), or null when it does not open
// (OpenCV's exceptions included).
std::unique_ptr<VideoReader> open_video(const std::string& path, int api);
// A video created for writing, or null when OpenCV cannot create it.
std::unique_ptr<VideoWriter> create_video(const std::string& path, int api, int fourcc, double fps, cv::Size size, bool colour);

// cv::VideoWriter::fourcc, without the library.
constexpr int fourcc(char a, char b, char c, char d) {
  return int(unsigned(a) & 255u) | int((unsigned(b) & 255u) << 8) | int((unsigned(c) & 255u) << 16) | int((unsigned(d) & 255u) << 24);
}

}  // namespace haptex::media
