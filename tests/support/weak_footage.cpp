#include "tests/support/weak_footage.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

namespace haptex::capture::fixtures {

std::vector<cv::Mat> press_sequence(const cv::Mat& no_contact, const cv::Mat& pressed, const PressTiming& t) {
  cv::Mat bg, press;
  no_contact.convertTo(bg, CV_32FC3);
  pressed.convertTo(press, CV_32FC3);
  std::vector<cv::Mat> seq(std::size_t(t.before), bg);
  const auto blend = [&](double k) { return cv::Mat(bg + (press - bg) * k); };
  for (int k = 1; k <= t.ramp; ++k) seq.push_back(blend(double(k) / t.ramp));
  for (int k = 0; k < t.hold; ++k) seq.push_back(press);
  for (int k = t.ramp - 1; k >= 0; --k) seq.push_back(blend(double(k) / t.ramp));
  for (int k = 0; k < t.after; ++k) seq.push_back(bg);
  return seq;
}

std::vector<cv::Mat> still_sequence(const cv::Mat& no_contact, int frames) {
  cv::Mat bg;
  no_contact.convertTo(bg, CV_32FC3);
  return std::vector<cv::Mat>(std::size_t(frames), bg);
}

void write_weak_video(const std::string& path, const std::vector<cv::Mat>& frames, const cv::Mat& no_contact,
                      const Degradation& d, int fourcc) {
  // Degraded at the output size: contrast and drift are linear, so shrinking first gives the same
  // picture at a fraction of the cost (the suite's time budget). Noise drawn per full-size pixel and
  // then area-averaged over k x k pixels would be k times weaker: it is drawn that much weaker here.
  const double k = std::max(1.0, std::sqrt(double(no_contact.total()) / double(d.size.area())));
  cv::Mat bg, frame, small;
  cv::resize(no_contact, small, d.size, 0, 0, cv::INTER_AREA);
  small.convertTo(bg, CV_32FC3);
  // The drift's shape: 0.5 at the left edge to 1.5 at the right.
  cv::Mat shape(bg.size(), CV_32FC3);
  for (int x = 0; x < bg.cols; ++x) shape.col(x).setTo(cv::Scalar::all(1.0 + (x / double(bg.cols - 1) - 0.5)));
  cv::VideoWriter video(path, cv::CAP_FFMPEG, fourcc, 25.0, d.size);
  if (!video.isOpened()) throw std::runtime_error(path + ": OpenCV cannot write this codec");
  cv::RNG rng(d.seed);
  cv::Mat g(bg.size(), CV_32FC3), noise(bg.size(), CV_32FC3), out;
  const double n = double(frames.size());
  for (std::size_t i = 0; i < frames.size(); ++i) {
    cv::resize(frames[i], small, d.size, 0, 0, cv::INTER_AREA);
    small.convertTo(frame, CV_32FC3);
    cv::addWeighted(frame, d.contrast, bg, 1 - d.contrast, 0, g);  // bg + (frame - bg) * contrast
    cv::scaleAdd(shape, d.drift * double(i) / n, g, g);
    rng.fill(noise, cv::RNG::NORMAL, 0, d.noise / k);
    g += noise;
    g.convertTo(out, CV_8UC3);  // saturating
    video.write(out);
  }
}

namespace {

cv::Mat grey_blocks(const cv::Mat& bgr) {
  cv::Mat grey, f, small;
  cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
  grey.convertTo(f, CV_32F);
  cv::resize(f, small, {f.cols / 2, f.rows / 2}, 0, 0, cv::INTER_AREA);
  return small;
}

double median(std::vector<double> v) {
  auto mid = v.begin() + std::ptrdiff_t(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

}  // namespace

FootageContrast measure_contrast(const std::string& path, const std::vector<int>& no_contact_frames) {
  cv::VideoCapture video(path, cv::CAP_FFMPEG);
  std::vector<cv::Mat> frames;
  for (cv::Mat f; video.read(f);) frames.push_back(grey_blocks(f));
  if (frames.size() < 10) throw std::runtime_error(path + ": fewer than 10 frames");
  cv::Mat reference = cv::Mat::zeros(frames.front().size(), CV_32F);
  for (int i = 0; i < 10; ++i) reference += frames[std::size_t(i)] / 10.0;
  std::vector<double> curve;
  for (const auto& f : frames) {
    const cv::Mat d = f - reference;
    const double m = median(std::vector<double>(d.begin<float>(), d.end<float>()));
    curve.push_back(cv::mean(cv::abs(d - m))[0]);
  }
  FootageContrast c;
  c.contrast = *std::max_element(curve.begin(), curve.end());
  std::vector<double> quiet;
  for (int i : no_contact_frames)
    if (i < int(curve.size())) quiet.push_back(curve[std::size_t(i)]);
  c.noise = median(quiet);
  return c;
}

cv::Mat synthetic_gel() {
  cv::Mat gel(480, 640, CV_32FC3);
  for (int y = 0; y < gel.rows; ++y)
    for (int x = 0; x < gel.cols; ++x) {
      const double u = x / 639.0, v = y / 479.0;
      const double vignette = 1.0 - 0.5 * ((u - 0.5) * (u - 0.5) + (v - 0.5) * (v - 0.5));
      gel.at<cv::Vec3f>(y, x) = cv::Vec3f(float(90 + 60 * u), float(100 + 50 * v), float(150 - 50 * u)) * float(vignette);
    }
  for (int y = 30; y < gel.rows; y += 60)
    for (int x = 30; x < gel.cols; x += 60) cv::circle(gel, {x, y}, 5, cv::Scalar::all(40), cv::FILLED, cv::LINE_AA);
  cv::GaussianBlur(gel, gel, {0, 0}, 1.0);
  cv::Mat out;
  gel.convertTo(out, CV_8UC3);
  return out;
}

cv::Mat synthetic_gel_pressed() {
  cv::Mat gel;
  synthetic_gel().convertTo(gel, CV_32FC3);
  // A round patch of grains a few pixels wide, lit from one side: bright and dark flanks.
  cv::Mat relief = cv::Mat::zeros(gel.size(), CV_32F);
  cv::RNG rng(7);
  for (int k = 0; k < 400; ++k) {
    const double a = rng.uniform(0.0, 2 * CV_PI), r = 110 * std::sqrt(rng.uniform(0.0, 1.0));
    cv::circle(relief, {int(300 + r * std::cos(a)), int(250 + r * std::sin(a))}, rng.uniform(2, 5), cv::Scalar(1), cv::FILLED);
  }
  cv::GaussianBlur(relief, relief, {0, 0}, 1.5);
  cv::Mat shading;
  cv::Sobel(relief, shading, CV_32F, 1, 0, 3);
  cv::Mat channels[3];
  cv::split(gel, channels);
  for (auto& c : channels) c += shading * 60.0;
  cv::merge(channels, 3, gel);
  cv::Mat out;
  gel.convertTo(out, CV_8UC3);
  return out;
}

}  // namespace haptex::capture::fixtures
