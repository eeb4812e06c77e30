#include "synth/height_field.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <opencv2/core.hpp>
#include <random>

#include "core/error.hpp"

namespace haptex::synth {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

int wrap(int i, int n) { return ((i % n) + n) % n; }

// Angular wavenumber of DFT index i on an n-point grid of length period: the negative half above n/2.
double wavenumber(int i, int n, double period) { return kTwoPi * double(i <= n / 2 ? i : i - n) / period; }

// Random roughness with an exponential-type autocorrelation: PSD ~ (1 + (k l)^2)^-1.5, whose power-law
// tail gives the fine detail real textures have. Anisotropy stretches the correlation along angle_rad.
cv::Mat random_roughness(const SurfaceRecipe& recipe, std::uint64_t seed, int n, double period) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<float> gauss(0.0f, 1.0f);
  const double along = recipe.correlation_mm, across = recipe.correlation_mm / std::max(1.0, recipe.anisotropy);
  const double c = std::cos(recipe.angle_rad), s = std::sin(recipe.angle_rad);
  cv::Mat spectrum(n, n, CV_32FC2);
  for (int v = 0; v < n; ++v) {
    const double ky = wavenumber(v, n, period);
    auto* row = spectrum.ptr<cv::Vec2f>(v);
    for (int u = 0; u < n; ++u) {
      const double kx = wavenumber(u, n, period);
      const double k_along = kx * c + ky * s, k_across = -kx * s + ky * c;
      const double q2 = k_along * k_along * along * along + k_across * k_across * across * across;
      const float amplitude = (u == 0 && v == 0) ? 0.0f : float(std::pow(1.0 + q2, -0.75));
      row[u] = {amplitude * gauss(rng), amplitude * gauss(rng)};
    }
  }
  cv::Mat field;
  cv::dft(spectrum, field, cv::DFT_INVERSE | cv::DFT_SCALE);
  cv::Mat planes[2];
  cv::split(field, planes);
  cv::Scalar mean, deviation;
  cv::meanStdDev(planes[0], mean, deviation);
  return (planes[0] - mean[0]) * (recipe.rms_um * 1e-3 / std::max(deviation[0], 1e-30));
}

// The pattern's two wave vectors, rounded to whole cycles over the field so it tiles seamlessly.
struct WaveVectors {
  double k1x, k1y, k2x, k2y;
};

WaveVectors pattern_waves(const SurfaceRecipe& recipe, double period) {
  auto whole = [&](double angle) {
    const double cycles = period / recipe.pattern_period_mm;
    const double mx = std::round(cycles * std::cos(angle)), my = std::round(cycles * std::sin(angle));
    return std::pair{kTwoPi * mx / period, kTwoPi * my / period};
  };
  const auto [k1x, k1y] = whole(recipe.pattern_angle_rad);
  const auto [k2x, k2y] = whole(recipe.pattern_angle_rad + std::numbers::pi / 2);
  return {k1x, k1y, k2x, k2y};
}

// Pattern height in units of its peak-to-valley, about [-0.5, 0.5].
double pattern_shape(Pattern pattern, double a, double b) {
  switch (pattern) {
    case Pattern::grooves: return 0.5 * std::tanh(3 * std::cos(a)) / std::tanh(3.0);
    case Pattern::weave: return 0.4 * std::cos(a) * std::cos(b) + 0.1 * std::cos(2 * a);
    case Pattern::mesh: return 0.5 * (std::abs(std::cos(a)) + std::abs(std::cos(b))) - 0.5;
    case Pattern::dots: return std::pow(0.25 * (1 + std::cos(a)) * (1 + std::cos(b)), 4) - 0.5;
    case Pattern::none: break;
  }
  return 0;
}

void add_pattern(cv::Mat& field, const SurfaceRecipe& recipe, double period) {
  if (recipe.pattern == Pattern::none || recipe.pattern_height_um <= 0) return;
  const WaveVectors w = pattern_waves(recipe, period);
  const int n = field.rows;
  const double pixel = period / n, height = recipe.pattern_height_um * 1e-3;
  for (int iy = 0; iy < n; ++iy) {
    float* row = field.ptr<float>(iy);
    const double y = iy * pixel;
    for (int ix = 0; ix < n; ++ix) {
      const double x = ix * pixel;
      row[ix] += float(height * pattern_shape(recipe.pattern, w.k1x * x + w.k1y * y, w.k2x * x + w.k2y * y));
    }
  }
}

HeightField from_mat(const cv::Mat& field, double period) {
  HeightField h;
  h.n = field.rows;
  h.period_mm = period;
  h.height_mm.assign(field.ptr<float>(0), field.ptr<float>(0) + std::size_t(h.n) * std::size_t(h.n));
  return h;
}

}  // namespace

float HeightField::at(int ix, int iy) const { return height_mm[std::size_t(wrap(iy, n)) * std::size_t(n) + std::size_t(wrap(ix, n))]; }

// Cubic B-spline weights of the four samples around fraction t: the interpolant is twice
// continuously differentiable, so a probe path's second differences carry the surface's curvature,
// not kinks where the path crosses grid lines (as bilinear sampling would).
static std::array<double, 4> bspline_weights(double t) {
  const double t2 = t * t, t3 = t2 * t, u = 1 - t;
  return {u * u * u / 6, (3 * t3 - 6 * t2 + 4) / 6, (-3 * t3 + 3 * t2 + 3 * t + 1) / 6, t3 / 6};
}

double HeightField::sample(double x_mm, double y_mm) const {
  const double fx = x_mm / pixel_mm(), fy = y_mm / pixel_mm();
  const double x0 = std::floor(fx), y0 = std::floor(fy);
  const auto wx = bspline_weights(fx - x0), wy = bspline_weights(fy - y0);
  const int ix = int(std::fmod(x0, n)), iy = int(std::fmod(y0, n));
  double sum = 0;
  for (int j = 0; j < 4; ++j) {
    double row = 0;
    for (int i = 0; i < 4; ++i) row += wx[std::size_t(i)] * at(ix - 1 + i, iy - 1 + j);
    sum += wy[std::size_t(j)] * row;
  }
  return sum;
}

HeightField make_height_field(const SurfaceRecipe& recipe, std::uint64_t seed, int n, double period_mm) {
  if (n < 8 || (n & (n - 1)) != 0) throw failure("make_height_field: n must be a power of two >= 8, not " + std::to_string(n));
  cv::Mat field = random_roughness(recipe, seed, n, period_mm);
  add_pattern(field, recipe, period_mm);
  return from_mat(field, period_mm);
}

HeightField smoothed_for_tip(const HeightField& field, double tip_radius_mm) {
  // A sphere of radius R pressed a depth d into a surface touches it over a patch of radius
  // sqrt(R d); a haptic probe under about 1 N sinks some 2 micrometres.
  constexpr double kIndentationMm = 0.002;
  const double sigma = std::sqrt(tip_radius_mm * kIndentationMm);
  const int n = field.n;
  cv::Mat spatial(n, n, CV_32F, const_cast<float*>(field.height_mm.data()));
  cv::Mat spectrum;
  cv::dft(spatial, spectrum, cv::DFT_COMPLEX_OUTPUT);
  for (int v = 0; v < n; ++v) {
    const double ky = wavenumber(v, n, field.period_mm);
    auto* row = spectrum.ptr<cv::Vec2f>(v);
    for (int u = 0; u < n; ++u) {
      const double kx = wavenumber(u, n, field.period_mm);
      row[u] *= float(std::exp(-0.5 * (kx * kx + ky * ky) * sigma * sigma));
    }
  }
  cv::Mat smoothed;
  cv::dft(spectrum, smoothed, cv::DFT_INVERSE | cv::DFT_SCALE | cv::DFT_REAL_OUTPUT);
  return from_mat(smoothed, field.period_mm);
}

}  // namespace haptex::synth
