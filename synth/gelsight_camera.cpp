#include "synth/gelsight_camera.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace haptex::synth {
namespace {

// Relative illumination of a simple lens: falls off with the square of the distance from the centre,
// reaching 1 - strength in the corners.
cv::Mat make_vignette(int width, int height, double strength) {
  cv::Mat vignette(height, width, CV_32F);
  const double cx = 0.5 * (width - 1), cy = 0.5 * (height - 1);
  const double corner2 = cx * cx + cy * cy;
  for (int v = 0; v < height; ++v) {
    float* row = vignette.ptr<float>(v);
    for (int u = 0; u < width; ++u) {
      const double r2 = ((u - cx) * (u - cx) + (v - cy) * (v - cy)) / std::max(corner2, 1.0);
      row[u] = float(1.0 - strength * r2);
    }
  }
  return vignette;
}

// The standard normal quantile function by bisection on erfc: exact enough for a 256-entry table
// and free of approximation constants.
double normal_quantile(double p) {
  double lo = -10, hi = 10;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (0.5 * std::erfc(-mid / std::sqrt(2.0)) < p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// 256 equally likely noise values: a uniform random byte picks one. Rescaled so the table's standard
// deviation is exactly sigma (its tails stop at about 2.9 sigma, which 8-bit frames cannot tell apart).
std::array<float, 256> make_noise_lut(double sigma) {
  std::array<double, 256> q{};
  double square = 0;
  for (int i = 0; i < 256; ++i) {
    q[i] = normal_quantile((i + 0.5) / 256.0);
    square += q[i] * q[i];
  }
  const double scale = sigma / std::sqrt(square / 256.0);
  std::array<float, 256> lut{};
  for (int i = 0; i < 256; ++i) lut[i] = float(q[i] * scale);
  return lut;
}

// SplitMix64: eight noise bytes per step, the same sequence on every platform and fast enough that
// the noise costs about a millisecond per 960 x 720 frame.
struct ByteStream {
  std::uint64_t state, word = 0;
  int left = 0;
  explicit ByteStream(std::uint64_t seed) : state(seed) {}
  unsigned next() {
    if (left == 0) {
      std::uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
      z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
      z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
      word = z ^ (z >> 31);
      left = 8;
    }
    const unsigned byte = unsigned(word & 0xFF);
    word >>= 8;
    --left;
    return byte;
  }
};

const CameraOptions& validated(const CameraOptions& options) {
  if (options.width < 8 || options.height < 8)
    throw failure("GelSightCamera: the image must be at least 8 x 8 pixels, not " + std::to_string(options.width) +
                  " x " + std::to_string(options.height));
  if (!(options.noise_grey >= 0) || !(options.vignetting >= 0 && options.vignetting < 1))
    throw failure("GelSightCamera: noise must be >= 0 and vignetting in [0, 1)");
  return options;
}

std::uint8_t to_grey(float value) {
  if (value <= 0.0f) return 0;
  if (value >= 255.0f) return 255;
  return std::uint8_t(value + 0.5f);
}

}  // namespace

GelSightCamera::GelSightCamera(CameraOptions options)
    : options_(validated(options)),
      vignette_(make_vignette(options.width, options.height, options.vignetting)),
      noise_lut_(make_noise_lut(options.noise_grey)) {}

cv::Mat GelSightCamera::expose(const cv::Mat& radiance, double exposure_gain, std::uint64_t noise_seed) const {
  if (radiance.type() != CV_32FC3 || radiance.cols != options_.width || radiance.rows != options_.height)
    throw failure("GelSightCamera::expose: expected a " + std::to_string(options_.width) + " x " +
                  std::to_string(options_.height) + " CV_32FC3 image");
  cv::Mat frame(options_.height, options_.width, CV_8UC3);
  ByteStream bytes(noise_seed);
  const float gain = float(exposure_gain);
  for (int v = 0; v < options_.height; ++v) {
    const float* in = radiance.ptr<float>(v);
    const float* vignette = vignette_.ptr<float>(v);
    std::uint8_t* out = frame.ptr<std::uint8_t>(v);
    for (int u = 0; u < options_.width; ++u) {
      const float scale = vignette[u] * gain;
      for (int c = 0; c < 3; ++c) out[3 * u + c] = to_grey(in[3 * u + c] * scale + noise_lut_[bytes.next()]);
    }
  }
  return frame;
}

}  // namespace haptex::synth
