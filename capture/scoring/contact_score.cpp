#include "capture/scoring/contact_score.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <opencv2/imgproc.hpp>

#ifdef __SSE2__
#include <emmintrin.h>
#endif

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

// The median of the leave-one-out scores and their robust spread (1.4826 x the median absolute
// deviation).
struct Spread {
  float level = 0, spread = 0;
};
Spread spread_of(std::vector<float> scores) {
  Spread s;
  auto middle = scores.begin() + std::ptrdiff_t(scores.size() / 2);
  std::nth_element(scores.begin(), middle, scores.end());
  s.level = *middle;
  for (float& v : scores) v = std::abs(v - s.level);
  std::nth_element(scores.begin(), middle, scores.end());
  s.spread = 1.4826f * *middle;
  return s;
}

cv::Mat centred(cv::Mat m) { return m - cv::mean(m)[0]; }

cv::Mat mean_of(const std::vector<cv::Mat>& frames) {
  cv::Mat sum = cv::Mat::zeros(frames.front().size(), CV_32F);
  for (const auto& f : frames) sum += f;
  return sum / double(frames.size());
}

// Each frame against the mean of the others: what a later no-contact frame scores.
std::vector<float> leave_one_out_scores(const std::vector<cv::Mat>& frames, float t) {
  const cv::Mat sum = mean_of(frames) * double(frames.size());
  std::vector<float> scores;
  for (const auto& f : frames) scores.push_back(contact_score(f, (sum - f) / double(frames.size() - 1), t));
  return scores;
}

// What a press would show: two frames in a row (the lower of the two). A lone odd frame, such as the
// first an encoder writes at another quality, is no press, as the segmenter judges it too.
float worst_two_in_a_row(const std::vector<float>& scores) {
  float worst = 0;
  for (std::size_t i = 1; i < scores.size(); ++i) worst = std::max(worst, std::min(scores[i - 1], scores[i]));
  return worst;
}

float footage_trigger(float level, const ScoreSettings& settings, float spread = 0) {
  return settings.trigger.value_or(
      level + std::max({settings.jitter_factor * spread, settings.level_factor * level, settings.min_trigger}));
}

}  // namespace

// Sums of the columns [1, g, x, y]: their Gram matrix and their moments with d = frame - reference.
struct DriftFit::Sums {
  cv::Matx44d gram = cv::Matx44d::zeros();
  cv::Vec4d moments = cv::Vec4d::all(0);
};

namespace {

// The residual of one pixel under the fit c, with the row's share of it (c0 + c3 y) taken out once.
struct Fit {
  Fit(const cv::Vec4d& c, float y) : row(float(c[0] + c[3] * y)), gain(float(c[1])), tilt(float(c[2])) {}
  float row, gain, tilt;  // c0 + c3 y_j, c1, c2
  float residual(float d, float g, float x) const { return d - row - gain * g - tilt * x; }
};

// The element v.size() / 2 of v sorted, for values >= 0 (NaN-free): their bit patterns sort as the
// values do, so a count of the top 12 bits finds the bucket that holds it, and only that bucket is
// sorted. A quarter of std::nth_element's time on a frame's 4000 samples, the same value.
float middle_of_nonnegative(std::vector<float>& v) {
  constexpr int kShift = 20;  // 2^12 buckets: sign (always 0), exponent and 3 bits of mantissa
  thread_local std::vector<std::uint32_t> count(std::size_t(1) << (32 - kShift));
  std::fill(count.begin(), count.end(), 0u);
  const auto bucket = [](float x) { return std::bit_cast<std::uint32_t>(x) >> kShift; };
  for (float x : v) ++count[bucket(x)];
  std::size_t rank = v.size() / 2, b = 0;
  while (rank >= count[b]) rank -= count[b++];
  const auto end = std::partition(v.begin(), v.end(), [&](float x) { return bucket(x) == b; });
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(rank), end);
  return v[rank];
}

// One row's sums over its pixels whose residual is beyond limit: count, g, x, gg, gx, xx, d, gd, xd
// (d = frame - reference). Four pixels at a time in SSE2, which every x86-64 has: GCC's vectoriser
// leaves a loop of nine sums scalar.
std::array<float, 9> outlier_row_sums(const float* f, const float* ref, const float* g, const float* x, int w,
                                      const Fit& fit, float limit) {
  std::array<float, 9> sum{};
  int i = 0;
#ifdef __SSE2__
  __m128 n = _mm_setzero_ps(), sg = n, sx = n, sgg = n, sgx = n, sxx = n, sd = n, sgd = n, sxd = n;
  const __m128 row = _mm_set1_ps(fit.row), gain = _mm_set1_ps(fit.gain), tilt = _mm_set1_ps(fit.tilt);
  const __m128 cut = _mm_set1_ps(limit), one = _mm_set1_ps(1.0f), sign = _mm_set1_ps(-0.0f);
  for (; i + 4 <= w; i += 4) {
    const __m128 gi = _mm_loadu_ps(g + i), xi = _mm_loadu_ps(x + i);
    const __m128 d = _mm_sub_ps(_mm_loadu_ps(f + i), _mm_loadu_ps(ref + i));
    const __m128 r = _mm_sub_ps(_mm_sub_ps(_mm_sub_ps(d, row), _mm_mul_ps(gain, gi)), _mm_mul_ps(tilt, xi));
    const __m128 o = _mm_and_ps(_mm_cmpgt_ps(_mm_andnot_ps(sign, r), cut), one);
    const __m128 og = _mm_mul_ps(o, gi), ox = _mm_mul_ps(o, xi);
    n = _mm_add_ps(n, o), sg = _mm_add_ps(sg, og), sx = _mm_add_ps(sx, ox);
    sgg = _mm_add_ps(sgg, _mm_mul_ps(og, gi)), sgx = _mm_add_ps(sgx, _mm_mul_ps(og, xi)), sxx = _mm_add_ps(sxx, _mm_mul_ps(ox, xi));
    sd = _mm_add_ps(sd, _mm_mul_ps(o, d)), sgd = _mm_add_ps(sgd, _mm_mul_ps(og, d)), sxd = _mm_add_ps(sxd, _mm_mul_ps(ox, d));
  }
  const __m128 acc[9] = {n, sg, sx, sgg, sgx, sxx, sd, sgd, sxd};
  for (int k = 0; k < 9; ++k) {
    alignas(16) float lanes[4];
    _mm_store_ps(lanes, acc[k]);
    sum[std::size_t(k)] = (lanes[0] + lanes[1]) + (lanes[2] + lanes[3]);
  }
#endif
  for (; i < w; ++i) {
    const float d = f[i] - ref[i];
    const float o = float(std::abs(fit.residual(d, g[i], x[i])) > limit);
    const float og = o * g[i], ox = o * x[i];
    const float terms[9] = {o, og, ox, og * g[i], og * x[i], ox * x[i], o * d, og * d, ox * d};
    for (std::size_t k = 0; k < 9; ++k) sum[k] += terms[k];
  }
  return sum;
}

}  // namespace

DriftFit::DriftFit(const cv::Mat& reference, bool gain) {
  CV_Assert(reference.type() == CV_32F && reference.isContinuous());
  // The columns: ones, centred x and y ramps (tilt) and the reference (gain), less its own mean and
  // ramps: all four orthogonal over the image, so that the sums of one frame, added up in float, solve
  // as well as the reference's in double. The fit spans what the reference and the ramps span either
  // way. A reference that is itself flat or a ramp (a gel lit evenly from one side) leaves nothing for
  // the gain column, which goes: any change but an offset and a tilt then counts, as without gain.
  const int w = reference.cols, h = reference.rows;
  x_.resize(std::size_t(w));
  y_.resize(std::size_t(h));
  for (int i = 0; i < w; ++i) x_[std::size_t(i)] = float((i + 0.5) / w - 0.5);
  for (int j = 0; j < h; ++j) y_[std::size_t(j)] = float((j + 0.5) / h - 0.5);
  centred_ = cv::Mat::zeros(reference.size(), CV_32F);
  if (gain) {
    centred_ = centred(reference.clone());
    double gx = 0, gy = 0, xx = 0, yy = 0, gg = 0;
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i) {
        const double g = centred_.at<float>(j, i), x = x_[std::size_t(i)], y = y_[std::size_t(j)];
        gx += g * x, gy += g * y, xx += x * x, yy += y * y, gg += g * g;
      }
    double left = 0;
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i) {
        float& g = centred_.at<float>(j, i);
        g = float(g - (xx > 0 ? gx / xx : 0.0) * x_[std::size_t(i)] - (yy > 0 ? gy / yy : 0.0) * y_[std::size_t(j)]);
        left += double(g) * g;
      }
    if (!(left > 1e-6 * gg)) centred_ = cv::Mat::zeros(reference.size(), CV_32F);
  }
  const Sums all = outliers(reference, reference, cv::Vec4d::all(0), -1);  // a negative cut: every pixel
  gram_ = all.gram;
  cv::invert(gram_, inverse_, cv::DECOMP_SVD);  // an empty gain column is dropped
}

// The sums over the pixels whose residual under c is beyond cut: the kept pixels' sums are the whole
// image's less these. Per row in float (a row is a few hundred pixels) and over rows in double; the
// y column is constant along a row, so its entries come from the row sums.
DriftFit::Sums DriftFit::outliers(const cv::Mat& image, const cv::Mat& reference, const cv::Vec4d& c, double cut) const {
  Sums out;
  const float *x = x_.data(), limit = float(cut);
  for (int j = 0; j < image.rows; ++j) {
    const float *f = image.ptr<float>(j), *ref = reference.ptr<float>(j), *g = centred_.ptr<float>(j);
    const Fit fit(c, y_[std::size_t(j)]);
    const auto [n, sg, sx, sgg, sgx, sxx, sd, sgd, sxd] = outlier_row_sums(f, ref, g, x, image.cols, fit, limit);
    const double y = y_[std::size_t(j)];
    const double row[4][4] = {{n, sg, sx, y * n}, {0, sgg, sgx, y * sg}, {0, 0, sxx, y * sx}, {0, 0, 0, y * y * n}};
    for (int a = 0; a < 4; ++a)
      for (int b = a; b < 4; ++b) out.gram(a, b) += row[a][b];
    out.moments += cv::Vec4d(sd, sgd, sxd, y * sd);
  }
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < a; ++b) out.gram(a, b) = out.gram(b, a);
  return out;
}

// The moments over every pixel (the Gram matrix of every pixel is the reference's): the first fit. The
// pixel loops are written for the compiler to vectorise (#pragma omp simd, -fopenmp-simd: no OpenMP
// runtime); a frame is scored every 1/30 s or faster (docs/capture.md, "Speed").
cv::Vec4d DriftFit::moments(const cv::Mat& image, const cv::Mat& reference) const {
  const float* x = x_.data();
  cv::Vec4d total = cv::Vec4d::all(0);
  for (int j = 0; j < image.rows; ++j) {
    const float *f = image.ptr<float>(j), *ref = reference.ptr<float>(j), *g = centred_.ptr<float>(j);
    float sd = 0, sgd = 0, sxd = 0;
#pragma omp simd reduction(+ : sd, sgd, sxd)
    for (int i = 0; i < image.cols; ++i) {
      const float d = f[i] - ref[i];
      sd += d, sgd += g[i] * d, sxd += x[i] * d;
    }
    total += cv::Vec4d(sd, sgd, sxd, double(y_[std::size_t(j)]) * sd);
  }
  return total;
}

// The median of |residual| over about 4000 pixels spread over the image (a stride with no factor in
// common with the width, so the samples cover every column): as good an estimate of the spread as all
// of them, in a fraction of the time.
double DriftFit::median_abs_residual(const cv::Mat& image, const cv::Mat& reference, const cv::Vec4d& c) const {
  const std::size_t n = image.total(), w = std::size_t(image.cols);
  std::size_t stride = std::max<std::size_t>(1, n / 4096);
  while (stride > 1 && std::gcd(stride, w) != 1) ++stride;
  const float *f = image.ptr<float>(), *ref = reference.ptr<float>(), *g = centred_.ptr<float>();
  thread_local std::vector<float> v;  // kept: scoring a stream of frames does not allocate
  v.clear();
  for (std::size_t k = 0; k < n; k += stride) {
    const std::size_t i = k % w, j = k / w;
    const Fit fit(c, y_[j]);
    v.push_back(std::abs(fit.residual(f[k] - ref[k], g[k], x_[i])));
  }
  return middle_of_nonnegative(v);
}

float DriftFit::score(const cv::Mat& image, const cv::Mat& reference, float pixel_threshold) const {
  CV_Assert(image.type() == CV_32F && reference.type() == CV_32F && image.size() == reference.size() && image.isContinuous() &&
            reference.isContinuous() && image.size() == centred_.size());
  // Least squares over every pixel (the Gram matrix's inverse is the reference's), then again over the
  // pixels that fit (|r| within 3 robust standard deviations): a press pulls the first fit, not the second.
  const cv::Vec4d all = moments(image, reference);
  cv::Vec4d c = inverse_ * all;
  const double cut = 3 * 1.4826 * median_abs_residual(image, reference, c);
  if (cut > 0) {
    const Sums out = outliers(image, reference, c, cut);
    cv::solve(gram_ - out.gram, all - out.moments, c, cv::DECOMP_SVD);
  }
  const float t = pixel_threshold, *x = x_.data();
  double total = 0;
  for (int j = 0; j < image.rows; ++j) {
    const float *f = image.ptr<float>(j), *ref = reference.ptr<float>(j), *g = centred_.ptr<float>(j);
    const Fit fit(c, y_[std::size_t(j)]);
    float row = 0;
#pragma omp simd reduction(+ : row)
    for (int i = 0; i < image.cols; ++i) row += std::max(0.0f, std::abs(fit.residual(f[i] - ref[i], g[i], x[i])) - t);
    total += row;
  }
  return float(total / double(image.total()));
}

float contact_score(const cv::Mat& image, const cv::Mat& reference, float pixel_threshold) {
  return DriftFit(reference).score(image, reference, pixel_threshold);
}

int calibration_frames(double fps) {
  constexpr int kFewest = 10, kMost = 25;
  if (!(fps > 0)) return kMost;
  return int(std::clamp(std::lround(fps), long(kFewest), long(kMost)));
}

void require_reference_frames(int count) {
  if (count < kMinReferenceFrames || count > kMaxReferenceFrames)
    throw input_error("--reference-frames", std::to_string(count),
                      "must be " + std::to_string(kMinReferenceFrames) + " to " + std::to_string(kMaxReferenceFrames),
                      "Give " + std::to_string(kMinReferenceFrames) + " to " + std::to_string(kMaxReferenceFrames) +
                          " no-contact frames (docs/capture.md, \"The thresholds\")");
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

namespace {

// The first half's mean against the second half's: well under a single frame's level for noise (each
// mean holds half the frames, and t removes most of what is left), more than the level for a press
// coming or going. The frame least like the others is left out: a lone odd frame, such as the first
// an encoder writes at another quality, would move its half's mean as a press does.
float trend_of(const std::vector<cv::Mat>& frames, const std::vector<float>& scores, float t) {
  const std::size_t odd = std::size_t(std::max_element(scores.begin(), scores.end()) - scores.begin());
  std::vector<const cv::Mat*> kept;
  for (std::size_t i = 0; i < frames.size(); ++i)
    if (i != odd || frames.size() < 4) kept.push_back(&frames[i]);
  const std::size_t half = kept.size() / 2;
  cv::Mat early = cv::Mat::zeros(frames.front().size(), CV_32F), late = early.clone();
  for (std::size_t i = 0; i < kept.size(); ++i) (i < half ? early : late) += *kept[i];
  // Without the gain term: a press in the reference is part of the reference image the gain scales.
  const cv::Mat late_mean = late / double(kept.size() - half);
  return DriftFit(late_mean, false).score(early / double(half), late_mean, t);
}

// The later frames free of contact: those scoring under the trigger their quietest quarter would set
// (with t from the noise of all of them: a press moves too few pixels to move its median). A press in
// the calibration second scores above it, and would otherwise raise the noise, the level and the
// trigger until no press stood out (a press in most of those frames moved their median).
std::vector<cv::Mat> quiet_frames(const std::vector<cv::Mat>& later, const cv::Mat& reference, const DriftFit& fit,
                                  const ScoreSettings& settings) {
  const float t = settings.pixel_threshold.value_or(0.0f);
  std::vector<float> scores;
  for (const auto& f : later) scores.push_back(fit.score(f, reference, t));
  std::vector<float> sorted = scores;
  auto quarter = sorted.begin() + std::ptrdiff_t(sorted.size() / 4);
  std::nth_element(sorted.begin(), quarter, sorted.end());
  ScoreSettings own = settings;
  own.trigger.reset();  // the bar is the footage's, whatever trigger the user set for the presses
  const float quiet = footage_trigger(*quarter, own);
  std::vector<cv::Mat> kept;
  for (std::size_t i = 0; i < later.size(); ++i)
    if (scores[i] <= quiet) kept.push_back(later[i]);
  return kept;
}

// The share of the change from `reference` to `later` (their mean |residual| under an offset, a gain and
// a tilt) that is left under a lighting model as well: the reference's grey squared (a gamma or exposure
// curve) and the position squared (light falling off towards the edges). A change of the light leaves
// little of itself; a contact, which moves some places and not others of the same grey, leaves most.
float share_beyond_lighting(const cv::Mat& reference, const cv::Mat& later) {
  const int w = reference.cols, h = reference.rows, n = w * h;
  double lo = 0, hi = 0;
  cv::minMaxLoc(reference, &lo, &hi);
  const double span = hi > lo ? hi - lo : 1.0;
  cv::Mat design(n, 8, CV_64F), change(n, 1, CV_64F);
  for (int j = 0, k = 0; j < h; ++j)
    for (int i = 0; i < w; ++i, ++k) {
      const double g = (reference.at<float>(j, i) - lo) / span - 0.5, x = (i + 0.5) / w - 0.5, y = (j + 0.5) / h - 0.5;
      const double row[8] = {1, g, x, y, g * g, x * x, y * y, x * y};
      std::copy(row, row + 8, design.ptr<double>(k));
      change.at<double>(k) = double(later.at<float>(j, i)) - reference.at<float>(j, i);
    }
  const auto left = [&](int terms) {
    const cv::Mat a = design.colRange(0, terms);
    cv::Mat c;
    cv::solve(a, change, c, cv::DECOMP_SVD);
    return cv::norm(change - a * c, cv::NORM_L1) / n;
  };
  const double plain = left(4);
  return plain > 0 ? float(left(8) / plain) : 0.0f;
}

// How much more the most changed part of the image changed than the typical part: the mean |change|
// (less its mean) over each block of an 8 x 6 grid, the largest over the median. Something touching
// the gel changes some places and not others; noise, a codec's texture and the light change the
// whole image alike (1.2 to 1.5 in still H.264 clips, 6 to 39 for grasps).
float concentration(const cv::Mat& reference, const cv::Mat& later) {
  cv::Mat change = later - reference;
  change = cv::abs(change - cv::mean(change)[0]);
  constexpr int kAcross = 8, kDown = 6;
  const int w = change.cols / kAcross, h = change.rows / kDown;
  std::vector<float> blocks;
  for (int by = 0; by < kDown; ++by)
    for (int bx = 0; bx < kAcross; ++bx) blocks.push_back(float(cv::mean(change(cv::Rect(bx * w, by * h, w, h)))[0]));
  const float largest = *std::max_element(blocks.begin(), blocks.end());
  std::nth_element(blocks.begin(), blocks.begin() + std::ptrdiff_t(blocks.size() / 2), blocks.end());
  const float median = blocks[blocks.size() / 2];
  return median > 0 ? largest / median : (largest > 0 ? INFINITY : 1.0f);
}

// Calibration frames hold a steady contact, not noise, when all of these hold (docs/capture.md, "The
// thresholds"): their level against the reference is over kHeldContact times their own per-pixel noise
// (1 of PhysiCLeAR's 473 press videos over 2.5, the 95th percentile 1.52; grasps held from the first
// second up to 9.9); they are not copies of one another (kCopiesNoise: copies say nothing of noise);
// over kBeyondLighting of the change is left beyond a change of the light (review 17, F1); and the change
// is concentrated, its most changed block over kConcentrated times the median one (F2, F5: an
// inter-frame codec's groups of pictures, and live noise after stale copies, change the image alike).
constexpr float kHeldContact = 2.5f, kBeyondLighting = 0.5f, kConcentrated = 2.0f;
// A camera's own noise is tenths of a grey level after the scoring image's blur; copies show none.
constexpr float kCopiesNoise = 0.01f;

}  // namespace

ContactReference ContactReference::from_frames(const std::vector<cv::Mat>& frames, const ScoreSettings& settings) {
  if (frames.size() < 2) throw failure("internal: a contact reference from frames needs at least two of them");
  const cv::Mat mean = mean_of(frames);
  const float noise = temporal_noise(frames, mean);
  const float t = settings.pixel_threshold.value_or(0.0f);
  const std::vector<float> scores = leave_one_out_scores(frames, t);
  const Spread s = spread_of(scores);
  ContactReference r(mean, noise, t, footage_trigger(s.level, settings, s.spread), s.level, s.spread);
  r.worst_reference_score_ = worst_two_in_a_row(scores);
  r.reference_limit_ = r.trigger_;
  // A press during the reference frames raises most of their scores, and so the level it would be
  // judged by; but it changes the image from the first frames to the last, where noise does not.
  // The floor: a noise-free source has a level of 0, which a change nobody sees would pass.
  r.trend_ = trend_of(frames, scores, t);
  r.trend_limit_ = std::max(s.level, settings.min_trigger);
  return r;
}

ContactReference ContactReference::from_calibration(const std::vector<cv::Mat>& frames, const std::vector<cv::Mat>& later,
                                                     const ScoreSettings& settings) {
  if (frames.size() < 2) throw failure("internal: a contact reference from frames needs at least two of them");
  ContactReference r = from_frames(frames, settings);
  // Fewer quiet frames measure no level worth judging by (a video cut short after its reference).
  constexpr std::size_t kFewestQuiet = 5;
  const std::vector<cv::Mat> quiet = later.size() >= kFewestQuiet ? quiet_frames(later, r.mean_, r.fit_, settings)
                                                                  : std::vector<cv::Mat>{};
  if (quiet.size() < kFewestQuiet) {
    r.trend_limit_ = INFINITY;  // the copies' own level is near 0, which any change would pass
    return r;
  }
  const cv::Mat later_mean = mean_of(quiet);
  const float noise = temporal_noise(quiet, later_mean);
  const float t = settings.pixel_threshold.value_or(0.0f);
  std::vector<float> scores;
  for (const auto& f : quiet) scores.push_back(r.fit_.score(f, r.mean_, t));
  const Spread s = spread_of(scores);
  const bool held = noise >= kCopiesNoise && s.level > kHeldContact * noise &&
                    share_beyond_lighting(r.mean_, later_mean) > kBeyondLighting &&
                    concentration(r.mean_, later_mean) > kConcentrated;
  // Held: a frame free of contact scores what the reference frames score among themselves, and the
  // quiet frames' spread is the contact's.
  const float level = held ? r.level_ : s.level, spread = held ? r.spread_ : s.spread;
  r = ContactReference(r.mean_, noise, t, footage_trigger(level, settings, spread), level, spread);
  r.held_contact_ = held;
  // Steadiness by the quiet frames' own leave-one-out level, as from_frames judges: their level
  // against the reference mean rises with a press in the reference, so it would excuse that press.
  const float own_level = spread_of(leave_one_out_scores(quiet, t)).level;
  const std::vector<float> reference_scores = leave_one_out_scores(frames, t);
  r.worst_reference_score_ = worst_two_in_a_row(reference_scores);
  r.reference_limit_ = footage_trigger(own_level, settings);
  r.trend_ = trend_of(frames, reference_scores, t);
  r.trend_limit_ = std::max(own_level, settings.min_trigger);
  return r;
}

ContactReference ContactReference::from_image(const cv::Mat& image, const ScoreSettings& settings) {
  return ContactReference(image.clone(), 0.0f, settings.pixel_threshold.value_or(settings.image_pixel_threshold),
                          settings.trigger.value_or(settings.image_trigger));
}

void ContactReference::take_thresholds(const ContactReference& other) {
  if (other.pixel_threshold_ != pixel_threshold_) throw failure("internal: thresholds taken from a reference with another per-pixel threshold");
  noise_ = other.noise_;
  level_ = other.level_;
  spread_ = other.spread_;
  trigger_ = other.trigger_;
}

SegmenterSettings ContactReference::segmenter(SegmenterSettings base) const {
  base.level = level_;
  base.trigger = trigger_;
  base.release = release();
  return base;
}

}  // namespace haptex::capture
