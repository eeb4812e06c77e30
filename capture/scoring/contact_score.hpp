#pragma once
// How much a frame differs from the no-contact reference, robust to sensor noise, compression and
// slow lighting drift, and when that is contact (docs/capture.md, "Finding presses"):
//
//   d     = frame - reference, per pixel of the scoring images (scoring_image.hpp)
//   r     = d - drift(d)         drift: the least-squares fit of an offset, a gain (a multiple of
//                                the reference: exposure and LED changes scale the image) and a tilt
//                                (x and y ramps: a light warming unevenly), refitted without the
//                                pixels that do not fit, so a press does not move it
//   score = mean over pixels of |r|                  in grey levels (a user's --pixel-threshold t: of
//                                                     max(0, |r| - t))
//
// With a reference taken from the footage itself (its no-contact frames, or a live take's), the
// trigger comes from that footage: each reference frame is scored against the mean of the others,
// which gives the no-contact level of the score and its jitter without a single extra frame
// (inter-frame video takes them over later frames instead: ContactReference::from_calibration), and
// contact is a score above that level by five times its jitter, and at least half the level. A mean
// over the whole image jitters far less than any pixel, so the statistic's own noise, not the
// pixels', sets the trigger, and a press of a few grey levels on a 320 x 240 MPEG-4 is found as surely
// as a deep one on a 3280 x 2464 MJPG. A single given no-contact image shows no noise: then a
// per-pixel threshold and the trigger are fixed floors.
#include <cmath>
#include <optional>
#include <vector>

#include <opencv2/core.hpp>

#include "capture/scoring/press_segmenter.hpp"

namespace haptex::capture {

// The no-contact frames averaged into a reference: enough for a quiet mean and for the steadiness
// rules to judge (docs/capture.md, "The thresholds"), few enough that their sum of 8-bit pixels fits
// 16 bits.
constexpr int kMinReferenceFrames = 10, kMaxReferenceFrames = 250;
// Throws haptex::Error (bad_input, naming --reference-frames) for a count outside those.
void require_reference_frames(int count);

// Inter-frame video: the no-contact frames after the reference whose scores set the level
// (ContactReference::from_calibration): a second of them, 10 to 25 (25 at 25 fps or more; 10 at 10 fps
// or less, where a second is all a short clip may leave before its press). An unknown rate (0) gives 25.
int calibration_frames(double fps);

struct ScoreSettings {
  // Footage: the score is the plain mean |residual| over the image (no per-pixel threshold: a
  // threshold set from single pixels' noise is itself too noisy on compressed footage), and
  //   trigger = level + max(jitter_factor x jitter, level_factor x level, min_trigger)
  // where jitter is the robust spread of the no-contact frames' scores: the statistic's own
  // frame-to-frame noise sets the trigger. The level term keeps compression steps and drift, which
  // jitter over a second does not show, from starting a press (docs/capture.md, "The thresholds",
  // has the figures they were chosen by).
  float jitter_factor = 5.0f;
  float level_factor = 0.5f;
  float min_trigger = 0.05f;  // grey levels: below any press a person sees
  // A single given image (its noise unknown): t and the trigger. Lossy images (JPEG) differ from
  // later frames by a few grey levels of compression; lossless ones (PNG) only by noise.
  float image_pixel_threshold = 6.0f;
  float image_trigger = 0.25f;
  // The user's --pixel-threshold and --trigger: replace what the rules above give.
  std::optional<float> pixel_threshold, trigger;
};

// The image floors for a given reference image of a lossless or lossy source.
ScoreSettings score_settings_for(bool lossless);

// The score of one image against a reference, building the drift fit for that reference (for
// single comparisons, as qa's; ContactReference keeps the fit for a stream of frames).
float contact_score(const cv::Mat& scoring_image, const cv::Mat& reference, float pixel_threshold);

// The drift fit of a reference, computed once: offset and gain (see above).
class DriftFit {
 public:
  // gain: fit a multiple of the reference too (off: any change but an offset counts).
  explicit DriftFit(const cv::Mat& reference, bool gain = true);
  float score(const cv::Mat& scoring_image, const cv::Mat& reference, float pixel_threshold) const;

 private:
  struct Sums;
  Sums outliers(const cv::Mat& image, const cv::Mat& reference, const cv::Vec4d& fit, double cut) const;
  cv::Vec4d moments(const cv::Mat& image, const cv::Mat& reference) const;
  double median_abs_residual(const cv::Mat& image, const cv::Mat& reference, const cv::Vec4d& fit) const;

  cv::Mat centred_;            // the gain column: the reference less its mean and ramps (zeros without gain)
  std::vector<float> x_, y_;   // the tilt columns, per image column and row
  cv::Matx44d gram_, inverse_; // the Gram matrix of [1, centred_, x, y] over every pixel, and its inverse
};

class ContactReference {
 public:
  // The mean of no-contact scoring images, with the thresholds their own scores give (see above).
  static ContactReference from_frames(const std::vector<cv::Mat>& scoring_images, const ScoreSettings& settings = {});
  // One given no-contact image: its noise is unknown, so the image floors apply.
  static ContactReference from_image(const cv::Mat& scoring_image, const ScoreSettings& settings = {});
  // A stored reference with stored thresholds (press files carry them; level and spread 0 when the
  // file predates them).
  ContactReference(cv::Mat mean, float noise, float pixel_threshold, float trigger, float level = 0, float spread = 0);

  float score(const cv::Mat& scoring_image) const { return fit_.score(scoring_image, mean_, pixel_threshold_); }
  const cv::Mat& mean() const { return mean_; }
  float noise() const { return noise_; }                   // robust per-pixel temporal standard deviation
  float pixel_threshold() const { return pixel_threshold_; }
  float level() const { return level_; }                   // the score of a no-contact frame (median)
  float spread() const { return spread_; }                 // its robust standard deviation
  float trigger() const { return trigger_; }               // a score above this is contact
  float release() const { return level_ + (trigger_ - level_) / 2; }  // a press ends below this
  // Inter-frame video (MPEG-4, H.264): its first frames copy each other's compression noise, so the
  // reference is the mean of `frames` but the noise, t, the level and the trigger come from the
  // no-contact frames `later` (ContactReference's rules above), leaving out those that score over the
  // trigger their quietest quarter sets: a press in up to three quarters of them. Steadiness is judged
  // by the leave-one-out level of those quiet frames (the copies' own is near 0). With fewer than five
  // quiet frames, the reference frames' own thresholds, and no trend. Quiet frames that all differ
  // from the reference far beyond their noise, in a concentrated change the light does not explain,
  // hold a contact (a grasp held from the first second): the level is then what the reference frames
  // show (held_contact(); the four conditions in contact_score.cpp and docs/capture.md).
  static ContactReference from_calibration(const std::vector<cv::Mat>& frames, const std::vector<cv::Mat>& later,
                                           const ScoreSettings& settings = {});
  bool held_contact() const { return held_contact_; }
  // The reference frames were a steady no-contact stretch: no two in a row count as contact, and
  // they do not change from the first to the last as a press coming or going does.
  bool steady() const { return worst_reference_score_ <= reference_limit_ && !trending(); }
  float worst_reference_score() const { return worst_reference_score_; }  // the lower of the worst two in a row
  float reference_limit() const { return reference_limit_; }  // what it must stay within: the trigger, as a rule
  // The first half of the reference frames against the second (the frame least like the others left
  // out), and the limit it must stay within: the no-contact level (at least min_trigger).
  bool trending() const { return trend_ > trend_limit_; }
  float trend() const { return trend_; }
  float trend_limit() const { return trend_limit_; }
  // The level, jitter and trigger of `other` (a calibration on other frames), keeping this
  // reference's image and its steadiness verdict. The per-pixel threshold must be the same.
  void take_thresholds(const ContactReference& other);
  // The segmentation thresholds, over the level, with the rest of `base`.
  SegmenterSettings segmenter(SegmenterSettings base) const;

 private:
  cv::Mat mean_;
  DriftFit fit_;
  float noise_ = 0, pixel_threshold_ = 0, trigger_ = 0, level_ = 0, spread_ = 0, worst_reference_score_ = 0;
  float reference_limit_ = INFINITY, trend_ = 0, trend_limit_ = INFINITY;
  bool held_contact_ = false;
};

}  // namespace haptex::capture
