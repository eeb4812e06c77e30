#pragma once
// Footage like the videos other labs share (docs/capture.md, "Finding presses"): small (320 x 240),
// lossy (MPEG-4 or MJPG), at 25 fps, where a press changes the blurred grey image by a grey level or
// two, the sensor adds noise, and the light drifts unevenly over the clip. Made from a no-contact
// image and a pressed one of any sensor, so the same test runs on synthetic gels and, when
// ../shared/data is present, on real captures.
#include <cmath>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace haptex::capture::fixtures {

// The frames of one press: `before` no-contact frames, a ramp of `ramp` frames, `hold` frames
// pressed, the ramp down and `after` no-contact frames (BGR, float).
struct PressTiming {
  int before = 40, ramp = 5, hold = 20, after = 40;
  int first_contact() const { return before; }                   // the first frame that differs
  int last_contact() const { return before + 2 * ramp + hold - 1; }
  int frames() const { return before + 2 * ramp + hold + after; }
};
std::vector<cv::Mat> press_sequence(const cv::Mat& no_contact, const cv::Mat& pressed, const PressTiming& timing = {});
std::vector<cv::Mat> still_sequence(const cv::Mat& no_contact, int frames);

struct Degradation {
  double contrast = 1;  // the press's change from the no-contact image, scaled
  double noise = 1.5;   // grey levels per full-size pixel and channel, Gaussian
  // Brightness added by the last frame, growing linearly over the clip: half of it on the image's
  // left edge, one and a half on its right (a light warming unevenly).
  double drift = 4;
  cv::Size size{320, 240};
  std::uint64_t seed = 1;
};

// Writes the frames, degraded, as a video with `fourcc` ('mp4v' MPEG-4 or 'MJPG') at 25 fps.
void write_weak_video(const std::string& path, const std::vector<cv::Mat>& frames, const cv::Mat& no_contact,
                      const Degradation& degradation, int fourcc);

// How a person would judge the clip, independent of haptex's score: per frame, the mean over the grey
// image (averaged in 2 x 2 blocks) of |d - median(d)|, d = frame - the mean of the first 10 frames.
// The press's contrast is the largest of these, the noise their median over no-contact frames.
struct FootageContrast {
  double contrast = 0, noise = 0;
  double ratio() const { return noise > 0 ? contrast / noise : INFINITY; }
};
FootageContrast measure_contrast(const std::string& video, const std::vector<int>& no_contact_frames);

// A GelSight-like synthetic gel at 640 x 480: the lit membrane (coloured light from the sides, a
// vignette, printed markers) and the same gel pressed by a sandpaper-like patch of grains.
cv::Mat synthetic_gel();
cv::Mat synthetic_gel_pressed();

}  // namespace haptex::capture::fixtures
