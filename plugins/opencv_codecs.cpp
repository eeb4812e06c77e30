// The codecs plugin (media/codecs.hpp): OpenCV's imgcodecs and videoio behind media/plugin.hpp's table.
// Built as libhaptex_opencv_codecs.so; only the haptex binary's commands that touch an image file or a
// video load it.
#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>

#include "media/plugin.hpp"

namespace haptex::media {
namespace {

class OpenCvReader final : public VideoReader {
 public:
  explicit OpenCvReader(cv::VideoCapture video) : video_(std::move(video)) {}
  bool read(cv::Mat& frame) override { return video_.read(frame); }
  bool grab() override { return video_.grab(); }
  bool retrieve(cv::Mat& frame) override { return video_.retrieve(frame); }
  double get(int property) const override { return video_.get(property); }
  bool set(int property, double value) override { return video_.set(property, value); }

 private:
  cv::VideoCapture video_;
};

class OpenCvWriter final : public VideoWriter {
 public:
  explicit OpenCvWriter(std::unique_ptr<cv::VideoWriter> video) : video_(std::move(video)) {}
  bool set(int property, double value) override { return video_->set(property, value); }
  void write(const cv::Mat& frame) override { video_->write(frame); }
  void release() override { video_->release(); }

 private:
  std::unique_ptr<cv::VideoWriter> video_;
};

bool encode(const std::string& extension, const cv::Mat& image, std::vector<unsigned char>& bytes, const std::vector<int>& parameters) {
  return cv::imencode(extension, image, bytes, parameters);
}

cv::Mat decode(cv::InputArray bytes, int flags) { return cv::imdecode(bytes, flags); }

cv::Mat read(const std::string& path, int flags) { return cv::imread(path, flags); }

VideoReader* open(const std::string& path, int api) {
  cv::VideoCapture video;
  try {
    video.open(path, api);
  } catch (const cv::Exception&) {
    return nullptr;
  }
  return video.isOpened() ? new OpenCvReader(std::move(video)) : nullptr;
}

VideoWriter* create(const std::string& path, int api, int fourcc, double fps, cv::Size size, bool colour) {
  auto video = std::make_unique<cv::VideoWriter>(path, api, fourcc, fps, size, colour);
  return video->isOpened() ? new OpenCvWriter(std::move(video)) : nullptr;
}

constexpr Plugin kTable{kPluginAbi, encode, decode, read, open, create};

}  // namespace
}  // namespace haptex::media

extern "C" __attribute__((visibility("default"))) const haptex::media::Plugin* haptex_opencv_codecs() { return &haptex::media::kTable; }
