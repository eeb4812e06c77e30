#pragma once
// How much a frame differs from the no-contact reference, robust to sensor noise and to slow
// exposure drift (the reasoning and the checks on real captures are in docs/capture.md):
//
//   d     = frame - reference, per pixel of the scoring images (scoring_image.hpp)
//   d'    = d - median(d)        a uniform brightness shift (exposure, LED drift) moves the median, not a press
//   score = mean over pixels of max(0, |d'| - t)
//
// t, the per-pixel noise threshold, is 4 times the reference frames' temporal noise and at least
// 6 grey levels (compression artefacts and sensor noise a single reference image cannot show), so
// noise adds (almost) nothing while a press adds its full depth times its area.
// The score is in grey levels: the mean excess over the noise threshold.
#include <vector>

#include <opencv2/core.hpp>

namespace haptex::capture {

struct ScoreSettings {
  float pixel_floor = 6.0f;        // t never below this (grey levels)
  float noise_multiplier = 4.0f;   // t = max(pixel_floor, noise_multiplier * noise)
  float trigger_floor = 0.25f;     // the contact trigger never below this (score units)
  float trigger_multiplier = 3.0f; // trigger = max(trigger_floor, trigger_multiplier * worst reference frame's score)
};

// The floors for a source. Lossy compression (MJPG, MPEG-4, JPEG images) changes no-contact frames by
// a few grey levels, and a single reference image cannot show how much, so lossy sources keep the
// floors above (checked on the real captures in ../shared/data). Lossless sources (PNG frames, FFV1,
// raw YUYV) with a measured reference change only by their noise, which the noise term covers: their
// floors are 1 grey level and a trigger of 0.02, so faint presses of clean (synthetic) sensors count.
ScoreSettings score_settings_for(bool lossless);

float contact_score(const cv::Mat& scoring_image, const cv::Mat& reference, float pixel_threshold);

class ContactReference {
 public:
  // The mean of no-contact scoring images, with their temporal noise and the thresholds it implies.
  static ContactReference from_frames(const std::vector<cv::Mat>& scoring_images, const ScoreSettings& settings = {});
  // One given no-contact image: its noise is unknown, so the floors apply.
  static ContactReference from_image(const cv::Mat& scoring_image, const ScoreSettings& settings = {});
  // A stored reference with stored thresholds (press files carry them).
  ContactReference(cv::Mat mean, float noise, float pixel_threshold, float trigger)
      : mean_(std::move(mean)), noise_(noise), pixel_threshold_(pixel_threshold), trigger_(trigger) {}

  float score(const cv::Mat& scoring_image) const { return contact_score(scoring_image, mean_, pixel_threshold_); }
  const cv::Mat& mean() const { return mean_; }
  float noise() const { return noise_; }                   // robust per-pixel temporal standard deviation
  float pixel_threshold() const { return pixel_threshold_; }
  float trigger() const { return trigger_; }               // a score above this is contact
  float release() const { return trigger_ / 2; }           // a press ends below this
  float worst_reference_score() const { return worst_reference_score_; }

 private:
  cv::Mat mean_;
  float noise_ = 0, pixel_threshold_ = 0, trigger_ = 0, worst_reference_score_ = 0;
};

}  // namespace haptex::capture
