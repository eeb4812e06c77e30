#include "capture/scoring/contact_score.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"

namespace haptex::capture {
namespace {

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

// The median of |value(i)| over at most about 32 000 evenly spread of n pixels: as good an estimate of
// a spread as all 126 000 of a 410 x 308 image, in a quarter of the time.
template <typename Value>
double median_abs(std::size_t n, const Value& value) {
  const std::size_t stride = std::max<std::size_t>(1, n / 32768);
  std::vector<double> v;
  v.reserve(n / stride + 1);
  for (std::size_t i = 0; i < n; i += stride) v.push_back(std::abs(value(i)));
  auto middle = v.begin() + std::ptrdiff_t(v.size() / 2);
  std::nth_element(v.begin(), middle, v.end());
  return *middle;
}

// The median of the leave-one-out scores and their robust spread (1.4826 x the median absolute
// deviation), and the largest.
struct Spread {
  float level = 0, spread = 0, worst = 0;
};
Spread spread_of(std::vector<float> scores) {
  Spread s;
  s.worst = *std::max_element(scores.begin(), scores.end());
  auto middle = scores.begin() + std::ptrdiff_t(scores.size() / 2);
  std::nth_element(scores.begin(), middle, scores.end());
  s.level = *middle;
  for (float& v : scores) v = std::abs(v - s.level);
  std::nth_element(scores.begin(), middle, scores.end());
  s.spread = 1.4826f * *middle;
  return s;
}

cv::Mat centred(cv::Mat m) { return m - cv::mean(m)[0]; }

float footage_trigger(float level, const ScoreSettings& settings) {
  return settings.trigger.value_or(level + std::max(settings.level_factor * level, settings.min_trigger));
}

}  // namespace

DriftFit::DriftFit(const cv::Mat& reference, bool gain) {
  CV_Assert(reference.type() == CV_32F && reference.isContinuous());
  centred_ = gain ? centred(reference.clone()) : cv::Mat::zeros(reference.size(), CV_32F);
  // The offset's column of ones is orthogonal to the centred reference; a flat reference (or no
  // gain) leaves the gain column empty and the pseudo-inverse drops it.
  const double g = centred_.dot(centred_);
  inverse_ = cv::Matx22d(1.0 / double(reference.total()), 0.0, 0.0, g > 0 ? 1.0 / g : 0.0);
}

float DriftFit::score(const cv::Mat& image, const cv::Mat& reference, float pixel_threshold) const {
  CV_Assert(image.type() == CV_32F && reference.type() == CV_32F && image.size() == reference.size() && image.isContinuous());
  const std::size_t n = image.total();
  const float *f = image.ptr<float>(), *ref = reference.ptr<float>(), *g = centred_.ptr<float>();
  const auto residual = [&](std::size_t i, const cv::Vec2d& c) { return double(f[i] - ref[i]) - c[0] - c[1] * g[i]; };
  // Least squares over every pixel, then again over the pixels that fit (|r| within 3 robust
  // standard deviations): a press pulls the first fit, not the second.
  cv::Vec2d moments(0, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const double d = double(f[i] - ref[i]);
    moments += cv::Vec2d(d, d * g[i]);
  }
  cv::Vec2d c = inverse_ * moments;
  const double cut = 3 * 1.4826 * median_abs(n, [&](std::size_t i) { return residual(i, c); });
  if (cut > 0) {
    cv::Matx22d gram = cv::Matx22d::zeros();
    moments = cv::Vec2d(0, 0);
    for (std::size_t i = 0; i < n; ++i) {
      if (std::abs(residual(i, c)) > cut) continue;
      const cv::Vec2d b(1.0, g[i]);
      gram += b * b.t();
      moments += b * double(f[i] - ref[i]);
    }
    cv::solve(gram, moments, c, cv::DECOMP_SVD);
  }
  double sum = 0;
  for (std::size_t i = 0; i < n; ++i) sum += std::max(0.0, std::abs(residual(i, c)) - double(pixel_threshold));
  return float(sum / double(n));
}

float contact_score(const cv::Mat& image, const cv::Mat& reference, float pixel_threshold) {
  return DriftFit(reference).score(image, reference, pixel_threshold);
}

ScoreSettings score_settings_for(bool lossless) {
  ScoreSettings s;
  if (lossless) {
    s.image_pixel_threshold = 1.0f;
    s.image_trigger = 0.02f;
  }
  return s;
}

ContactReference::ContactReference(cv::Mat mean, float noise, float pixel_threshold, float trigger, float level, float spread)
    : mean_(std::move(mean)),
      fit_(mean_),
      noise_(noise),
      pixel_threshold_(pixel_threshold),
      trigger_(trigger),
      level_(level),
      spread_(spread) {}

ContactReference ContactReference::from_frames(const std::vector<cv::Mat>& frames, const ScoreSettings& settings) {
  if (frames.size() < 2) throw failure("internal: a contact reference from frames needs at least two of them");
  cv::Mat sum = cv::Mat::zeros(frames.front().size(), CV_32F);
  for (const auto& f : frames) sum += f;
  cv::Mat mean = sum / double(frames.size());
  const float noise = temporal_noise(frames, mean);
  const float t = settings.pixel_threshold.value_or(settings.noise_threshold * noise);
  // Each frame against the mean of the others: what a later no-contact frame scores.
  std::vector<float> scores;
  for (const auto& f : frames) scores.push_back(contact_score(f, (sum - f) / double(frames.size() - 1), t));
  const Spread s = spread_of(scores);
  ContactReference r(mean, noise, t, footage_trigger(s.level, settings), s.level, s.spread);
  r.worst_reference_score_ = s.worst;
  // A press during the reference frames raises most of their scores, and so the level it would be
  // judged by; but it changes the image from the first frames to the last, where noise does not:
  // the first half's mean against the second half's scores about 0.6 of a single frame's level
  // for noise (each mean holds half the frames), more than the level for a press coming or going.
  const std::size_t half = frames.size() / 2;
  cv::Mat early = cv::Mat::zeros(mean.size(), CV_32F), late = cv::Mat::zeros(mean.size(), CV_32F);
  for (std::size_t i = 0; i < frames.size(); ++i) (i < half ? early : late) += frames[i];
  // Without the gain term: a press in the reference is part of the reference image the gain scales.
  const cv::Mat late_mean = late / double(frames.size() - half);
  const float trend = DriftFit(late_mean, false).score(early / double(half), late_mean, t);
  r.steady_limit_ = trend <= s.level ? r.trigger_ : -1.0f;
  return r;
}

ContactReference ContactReference::calibrated(const std::vector<float>& scores, const ScoreSettings& settings) const {
  std::vector<float> finite;
  for (float v : scores)
    if (std::isfinite(v)) finite.push_back(v);
  if (finite.empty() || settings.trigger || settings.pixel_threshold) return *this;
  const Spread s = spread_of(finite);
  ContactReference r(mean_, noise_, pixel_threshold_, footage_trigger(s.level, settings), s.level, s.spread);
  r.worst_reference_score_ = worst_reference_score_;
  r.steady_limit_ = r.trigger_;  // the reference frames' own noise says little here (inter-frame video)
  return r;
}

ContactReference ContactReference::from_image(const cv::Mat& image, const ScoreSettings& settings) {
  return ContactReference(image.clone(), 0.0f, settings.pixel_threshold.value_or(settings.image_pixel_threshold),
                          settings.trigger.value_or(settings.image_trigger));
}

SegmenterSettings ContactReference::segmenter(SegmenterSettings base) const {
  base.level = level_;
  base.trigger = trigger_;
  base.release = release();
  return base;
}

}  // namespace haptex::capture
