#include "synth/gelsight_renderer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <opencv2/imgproc.hpp>
#include <string>

#include "core/error.hpp"

namespace haptex::synth {
namespace {

// A GelSight's three LEDs shine from the gel's edge at low elevation, 120 degrees apart: a slope
// facing one light brightens its colour and dims the others, so colour encodes the surface normal.
struct Light {
  double azimuth_deg;
  cv::Vec3f colour;  // BGR grey levels reached when the light falls straight onto the skin
};
constexpr double kElevationDeg = 20;
const std::array<Light, 3> kLights = {{
    {90, {12, 16, 200}},   // red, from below the image centre
    {210, {14, 200, 16}},  // green
    {330, {200, 16, 12}},  // blue
}};
const cv::Vec3f kAmbient = {72, 70, 68};  // light scattered inside the gel: the skin's grey base

struct LightDirection {
  float x, y, z;
};

std::array<LightDirection, 3> light_directions() {
  std::array<LightDirection, 3> directions{};
  const double elevation = kElevationDeg * std::numbers::pi / 180;
  for (std::size_t k = 0; k < kLights.size(); ++k) {
    const double azimuth = kLights[k].azimuth_deg * std::numbers::pi / 180;
    directions[k] = {float(std::cos(elevation) * std::cos(azimuth)), float(std::cos(elevation) * std::sin(azimuth)),
                     float(std::sin(elevation))};
  }
  return directions;
}

// Lambertian shading of the skin z(x, y) from its slopes: normal (-zx, -zy, 1) / |...|.
cv::Mat shade_slopes(const cv::Mat& zx, const cv::Mat& zy) {
  const auto directions = light_directions();
  cv::Mat out(zx.size(), CV_32FC3);
  for (int v = 0; v < zx.rows; ++v) {
    const float* gx = zx.ptr<float>(v);
    const float* gy = zy.ptr<float>(v);
    float* pixel = out.ptr<float>(v);
    for (int u = 0; u < zx.cols; ++u) {
      const float inverse_norm = 1.0f / std::sqrt(1.0f + gx[u] * gx[u] + gy[u] * gy[u]);
      float b = kAmbient[0], g = kAmbient[1], r = kAmbient[2];
      for (std::size_t k = 0; k < kLights.size(); ++k) {
        const LightDirection& l = directions[k];
        const float lambert = std::max(0.0f, (l.z - gx[u] * l.x - gy[u] * l.y) * inverse_norm);
        b += lambert * kLights[k].colour[0];
        g += lambert * kLights[k].colour[1];
        r += lambert * kLights[k].colour[2];
      }
      pixel[3 * u] = b;
      pixel[3 * u + 1] = g;
      pixel[3 * u + 2] = r;
    }
  }
  return out;
}

cv::Mat field_mat(const HeightField& field) {
  if (field.n < 2 || field.period_mm <= 0 || field.height_mm.size() != std::size_t(field.n) * std::size_t(field.n))
    throw failure("GelSightRenderer: the height field is empty or its size does not match n x n");
  return cv::Mat(field.n, field.n, CV_32F, const_cast<float*>(field.height_mm.data())).clone();
}

// The resting gel: a sphere cap of this radius, apex at the image centre, approximated by its
// parabola r^2 / 2R (at 200 mm, the corners of the field of view fall 0.22 mm behind the apex).
struct Dome {
  cv::Mat sag, slope_x, slope_y;
};

Dome make_dome(int width, int height, double pixel_mm, double radius_mm) {
  Dome dome{cv::Mat::zeros(height, width, CV_32F), cv::Mat::zeros(height, width, CV_32F),
            cv::Mat::zeros(height, width, CV_32F)};
  if (radius_mm <= 0) return dome;
  for (int v = 0; v < height; ++v) {
    const double y = (v - 0.5 * (height - 1)) * pixel_mm;
    for (int u = 0; u < width; ++u) {
      const double x = (u - 0.5 * (width - 1)) * pixel_mm;
      dome.sag.at<float>(v, u) = float((x * x + y * y) / (2 * radius_mm));
      dome.slope_x.at<float>(v, u) = float(-x / radius_mm);
      dome.slope_y.at<float>(v, u) = float(-y / radius_mm);
    }
  }
  return dome;
}

CameraOptions camera_options(const RendererOptions& options) {
  return {options.width, options.height, options.noise_grey, options.vignetting};
}

}  // namespace

cv::Vec3f flat_gel_colour() {
  const auto directions = light_directions();
  cv::Vec3f colour = kAmbient;
  for (std::size_t k = 0; k < kLights.size(); ++k) colour += directions[k].z * kLights[k].colour;
  return colour;
}

GelSightRenderer::GelSightRenderer(const HeightField& field, RendererOptions options)
    : options_(options), camera_(camera_options(options)), field_(field_mat(field)), field_pixel_mm_(field.pixel_mm()) {
  if (!(options.field_width_mm > 0) || !(options.smoothing_deep_mm > 0) ||
      !(options.smoothing_shallow_mm >= options.smoothing_deep_mm) || !(options.smoothing_depth_mm > 0))
    throw failure("GelSightRenderer: the field of view and the smoothing widths must be positive, shallow >= deep");
  Dome dome = make_dome(options.width, options.height, pixel_mm(), options.gel_radius_mm);
  dome_sag_ = dome.sag;
  dome_slope_x_ = dome.slope_x;
  dome_slope_y_ = dome.slope_y;
  flat_ = shade_slopes(dome_slope_x_, dome_slope_y_);
}

double GelSightRenderer::smoothing_mm(double depth_mm) const {
  const double d = std::max(depth_mm, 0.0), half = options_.smoothing_depth_mm;
  return options_.smoothing_deep_mm + (options_.smoothing_shallow_mm - options_.smoothing_deep_mm) * half / (half + d);
}

cv::Mat GelSightRenderer::surface_under(const PressPose& pose) const {
  // Image pixel (u, v) sits at (x + u s, y + v s) mm; warpAffine samples the periodic field there.
  const double scale = pixel_mm() / field_pixel_mm_;
  const cv::Matx23d to_field(scale, 0, pose.x_mm / field_pixel_mm_, 0, scale, pose.y_mm / field_pixel_mm_);
  cv::Mat surface;
  cv::warpAffine(field_, surface, to_field, cv::Size(options_.width, options_.height),
                 cv::INTER_LINEAR | cv::WARP_INVERSE_MAP, cv::BORDER_WRAP);
  for (int v = 0; v < surface.rows; ++v) {
    float* row = surface.ptr<float>(v);
    const double y = (v - 0.5 * surface.rows) * pixel_mm();
    const float* sag = dome_sag_.ptr<float>(v);
    for (int u = 0; u < surface.cols; ++u)
      row[u] += float(pose.tilt_x * (u - 0.5 * surface.cols) * pixel_mm() + pose.tilt_y * y) - sag[u];
  }
  double highest = 0;
  cv::minMaxLoc(surface, nullptr, &highest);
  surface -= highest;
  return surface;
}

cv::Mat GelSightRenderer::shade(const cv::Mat& surface, double depth_mm) const {
  if (surface.type() != CV_32F || surface.size() != flat_.size())
    throw failure("GelSightRenderer::shade: the surface must come from surface_under()");
  if (depth_mm <= 0) return flat_.clone();
  // The gel takes the shape of what rises above (highest - depth), smoothed elastically.
  cv::Mat indentation;
  cv::max(surface + depth_mm, 0.0, indentation);
  const double sigma = smoothing_mm(depth_mm) / pixel_mm();
  const int half_width = int(std::ceil(3 * sigma));
  cv::GaussianBlur(indentation, indentation, cv::Size(2 * half_width + 1, 2 * half_width + 1), sigma, sigma,
                   cv::BORDER_REFLECT);
  cv::Mat zx, zy;  // slopes, mm per mm: Sobel's 3 x 3 kernel sums to 8 pixel steps
  cv::Sobel(indentation, zx, CV_32F, 1, 0, 3, 1.0 / (8 * pixel_mm()), 0, cv::BORDER_REFLECT);
  cv::Sobel(indentation, zy, CV_32F, 0, 1, 3, 1.0 / (8 * pixel_mm()), 0, cv::BORDER_REFLECT);
  return shade_slopes(zx + dome_slope_x_, zy + dome_slope_y_);
}

cv::Mat GelSightRenderer::render(double depth_mm, const PressPose& pose, double exposure_gain,
                                 std::uint64_t noise_seed) const {
  const cv::Mat shaded = depth_mm > 0 ? shade(surface_under(pose), depth_mm) : flat_;
  return expose(shaded, exposure_gain, noise_seed);
}

}  // namespace haptex::synth
