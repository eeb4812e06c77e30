#pragma once
// The camera half of a GelSight-type sensor: what turns the light leaving the gel into an 8-bit frame.
// Vignetting darkens the corners, the exposure gain drifts slowly over a press, and every pixel gets
// its own sensor noise. Both the height-field renderer and the photo presses use it, so synthetic and
// photograph-based videos carry the same camera artefacts.
#include <array>
#include <cstdint>
#include <opencv2/core.hpp>

namespace haptex::synth {

struct CameraOptions {
  int width = 960;
  int height = 720;
  double noise_grey = 1.0;  // standard deviation of the per-pixel noise, in grey levels
  double vignetting = 0.2;  // share of the brightness lost in the image corners (cos^4-like falloff)
};

class GelSightCamera {
 public:
  explicit GelSightCamera(CameraOptions options = {});

  const CameraOptions& options() const { return options_; }

  // One frame (CV_8UC3, OpenCV's BGR channel order) from the light reaching the sensor (CV_32FC3,
  // grey levels, width x height): radiance x vignetting x exposure_gain + noise, rounded and
  // clipped to 0..255. The noise is a pure function of noise_seed.
  cv::Mat expose(const cv::Mat& radiance, double exposure_gain, std::uint64_t noise_seed) const;

 private:
  CameraOptions options_;
  cv::Mat vignette_;                   // CV_32F, 1 at the centre
  std::array<float, 256> noise_lut_;  // Gaussian quantiles: one random byte -> one noise value
};

}  // namespace haptex::synth
