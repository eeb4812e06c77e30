#pragma once
// Frames of a GelSight-type tactile sensor pressed into a synthetic surface, rendered the way the
// sensor works: a clear elastomer with a reflective skin takes the shape of whatever rises into it;
// three coloured lights at low elevation shade that skin by its surface normals; a camera behind the
// gel records it (synth/gelsight_camera.hpp: vignetting, exposure drift, noise).
#include <cstdint>
#include <opencv2/core.hpp>

#include "synth/gelsight_camera.hpp"
#include "synth/height_field.hpp"

namespace haptex::synth {

struct RendererOptions {
  int width = 960;
  int height = 720;
  double field_width_mm = 15.0;  // the field of view across the image; its height follows the aspect ratio
  double noise_grey = 1.0;       // camera noise, standard deviation in grey levels
  double vignetting = 0.2;       // brightness lost in the image corners
  // The gel is a shallow dome (as on most GelSight sensors), so contact starts at one point and
  // spreads as the press deepens; the resting dome's slopes tint the edges of the no-contact image.
  // 0 makes a flat gel.
  double gel_radius_mm = 200;
  // The elastomer's smoothing of the surface it touches, as a Gaussian width: wide at first touch,
  // when the gel only drapes over the highest asperities, narrowing towards smoothing_deep_mm as a
  // deeper press pushes it into the valleys; halfway there at smoothing_depth_mm.
  double smoothing_shallow_mm = 0.12;
  double smoothing_deep_mm = 0.02;
  double smoothing_depth_mm = 0.02;
};

// Where the sensor meets the surface in one press. A hand-held press is never quite parallel: the
// tilt makes contact spread across the field of view as the press deepens.
struct PressPose {
  double x_mm = 0, y_mm = 0;      // the image's top-left corner in the (periodic) surface
  double tilt_x = 0, tilt_y = 0;  // the surface's slope relative to the gel, mm per mm along x and y
};

// The untouched gel's colour (BGR grey levels, before vignetting): the three lights on a flat skin.
cv::Vec3f flat_gel_colour();

class GelSightRenderer {
 public:
  GelSightRenderer(const HeightField& field, RendererOptions options = {});

  const RendererOptions& options() const { return options_; }
  double pixel_mm() const { return options_.field_width_mm / options_.width; }
  double period_mm() const { return field_pixel_mm_ * field_.cols; }  // of the height field

  // The surface in the field of view at this pose, as heights (mm, CV_32F, one per image pixel) over
  // the resting gel skin, shifted so the highest is 0: the gel first touches there. Sample once per press.
  cv::Mat surface_under(const PressPose& pose) const;
  // The light leaving the gel (CV_32FC3, BGR grey levels) pressed depth_mm into `surface` (from
  // surface_under); depth 0 is the flat gel. Noise-free, so a press can reuse it for equal depths.
  cv::Mat shade(const cv::Mat& surface, double depth_mm) const;
  // The camera's frame of a shaded image (CV_8UC3, BGR): vignetting, exposure gain, noise.
  cv::Mat expose(const cv::Mat& shaded, double exposure_gain, std::uint64_t noise_seed) const {
    return camera_.expose(shaded, exposure_gain, noise_seed);
  }
  // All three: one frame at this depth and pose.
  cv::Mat render(double depth_mm, const PressPose& pose, double exposure_gain, std::uint64_t noise_seed) const;

  // The Gaussian width (mm) of the elastomer's smoothing at this contact depth.
  double smoothing_mm(double depth_mm) const;

 private:
  RendererOptions options_;
  GelSightCamera camera_;
  cv::Mat field_;  // the height field, n x n CV_32F (mm)
  double field_pixel_mm_;
  cv::Mat dome_sag_;                // how far the resting skin falls away from its apex (mm)
  cv::Mat dome_slope_x_, dome_slope_y_;
  cv::Mat flat_;                    // shade() of the untouched gel
};

}  // namespace haptex::synth
