#include "capture/scoring/contact_score.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"

namespace haptex::capture {
namespace {

// The median of a continuous image; at most about 32 000 evenly spread pixels decide it, which
// estimates a uniform shift as well as all 126 000 of a 410 x 308 image would, in a quarter of the time.
float median_of(const cv::Mat& values) {
  CV_Assert(values.isContinuous());
  const std::size_t n = values.total(), stride = std::max<std::size_t>(1, n / 32768);
  const float* p = values.ptr<float>();
  std::vector<float> v;
  v.reserve(n / stride + 1);
  for (std::size_t i = 0; i < n; i += stride) v.push_back(p[i]);
  auto middle = v.begin() + std::ptrdiff_t(v.size() / 2);
  std::nth_element(v.begin(), middle, v.end());
  return *middle;
}

// Robust standard deviation of every pixel's deviation from the mean over all frames:
// 1.4826 x the median absolute deviation, unmoved by a few odd pixels.
float temporal_noise(const std::vector<cv::Mat>& frames, const cv::Mat& mean) {
  if (frames.size() < 2) return 0;
  std::vector<float> deviations;
  deviations.reserve(frames.size() * mean.total());
  cv::Mat d;
  for (const auto& f : frames) {
    cv::absdiff(f, mean, d);
    deviations.insert(deviations.end(), d.begin<float>(), d.end<float>());
  }
  auto middle = deviations.begin() + std::ptrdiff_t(deviations.size() / 2);
  std::nth_element(deviations.begin(), middle, deviations.end());
  // Each frame is part of the mean it is compared with, which shrinks its deviation by sqrt((n-1)/n).
  const double n = double(frames.size());
  return float(1.4826 * *middle * std::sqrt(n / (n - 1)));
}

}  // namespace

float contact_score(const cv::Mat& image, const cv::Mat& reference, float pixel_threshold) {
  CV_Assert(image.type() == CV_32F && reference.type() == CV_32F && image.size() == reference.size());
  cv::Mat d;
  cv::subtract(image, reference, d);
  const float shift = median_of(d);
  cv::absdiff(d, cv::Scalar(shift), d);
  cv::subtract(d, cv::Scalar(pixel_threshold), d);
  cv::threshold(d, d, 0, 0, cv::THRESH_TOZERO);
  return float(cv::mean(d)[0]);
}

ScoreSettings score_settings_for(bool lossless) {
  ScoreSettings s;
  if (lossless) {
    s.pixel_floor = 1.0f;
    s.trigger_floor = 0.02f;
  }
  return s;
}

ContactReference ContactReference::from_frames(const std::vector<cv::Mat>& frames, const ScoreSettings& settings) {
  if (frames.empty()) throw failure("internal: a contact reference needs at least one frame");
  cv::Mat sum = cv::Mat::zeros(frames.front().size(), CV_32F);
  for (const auto& f : frames) sum += f;
  cv::Mat mean = sum / double(frames.size());
  const float noise = temporal_noise(frames, mean);
  const float t = std::max(settings.pixel_floor, settings.noise_multiplier * noise);
  float worst = 0;
  for (const auto& f : frames) worst = std::max(worst, contact_score(f, mean, t));
  ContactReference r(mean, noise, t, std::max(settings.trigger_floor, settings.trigger_multiplier * worst));
  r.worst_reference_score_ = worst;
  return r;
}

ContactReference ContactReference::from_image(const cv::Mat& image, const ScoreSettings& settings) {
  return ContactReference(image.clone(), 0.0f, settings.pixel_floor, settings.trigger_floor);
}

}  // namespace haptex::capture
