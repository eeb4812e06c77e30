// One physical cause for look and feel: materials of one family are closer than materials of
// different families both in GelSight image features and in vibration spectra, and over 20 materials
// the two distances agree in rank.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <opencv2/imgproc.hpp>

#include "core/parallel.hpp"
#include "synth/gelsight_renderer.hpp"
#include "synth/material_families.hpp"
#include "synth/probe_vibration.hpp"
#include "synth/truth_spectra.hpp"

namespace haptex::synth {
namespace {

constexpr int kMaterials = 20;

// Image features a texture encoder might use: the radially averaged log power spectrum of the
// peak frame's difference from the untouched gel, on a grey image.
std::vector<double> image_features(const GelSightRenderer& renderer) {
  const PressPose pose{3.0, 4.0, 0, 0};
  const cv::Mat surface = renderer.surface_under(pose);
  cv::Mat pressed, flat;
  cv::cvtColor(renderer.shade(surface, 0.12), pressed, cv::COLOR_BGR2GRAY);
  cv::cvtColor(renderer.shade(surface, 0.0), flat, cv::COLOR_BGR2GRAY);
  cv::Mat difference = pressed - flat, spectrum;
  cv::dft(difference, spectrum, cv::DFT_COMPLEX_OUTPUT);
  constexpr int kRings = 24;
  std::vector<double> power(kRings, 1e-12);
  const int rows = spectrum.rows, cols = spectrum.cols;
  for (int v = 0; v < rows; ++v)
    for (int u = 0; u < cols; ++u) {
      const double fy = double(v <= rows / 2 ? v : v - rows) / rows, fx = double(u <= cols / 2 ? u : u - cols) / cols;
      const int ring = int(std::sqrt(fx * fx + fy * fy) / 0.5 * kRings);
      if (ring >= 1 && ring < kRings) {
        const cv::Vec2f x = spectrum.at<cv::Vec2f>(v, u);
        power[std::size_t(ring)] += double(x[0]) * x[0] + double(x[1]) * x[1];
      }
    }
  std::vector<double> features;
  for (int ring = 1; ring < kRings; ++ring) features.push_back(std::log10(power[std::size_t(ring)]));
  return features;
}

// The material's feel: its mean log amplitude spectrum over a force-speed grid.
std::vector<double> spectrum_features(const ProbeVibration& probe) {
  const dataset::TruthGrid grid = expected_spectra(probe, {200, 4}, 5, {3, 2, 4});
  std::vector<double> mean(100, 0.0);
  const std::size_t points = grid.speeds_mm_s.size() * grid.forces_n.size();
  for (std::size_t p = 0; p < points; ++p)
    for (std::size_t k = 0; k < 100; ++k) mean[k] += grid.spectra[p * 100 + k] / double(points);
  for (double& m : mean) m = std::log10(m + 1e-9);
  return mean;
}

double distance(const std::vector<double>& a, const std::vector<double>& b) {
  double sum = 0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(sum);
}

std::vector<double> ranks(const std::vector<double>& x) {
  std::vector<std::size_t> order(x.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return x[a] < x[b]; });
  std::vector<double> r(x.size());
  for (std::size_t i = 0; i < order.size(); ++i) r[order[i]] = double(i);
  return r;
}

double spearman(const std::vector<double>& a, const std::vector<double>& b) {
  const std::vector<double> ra = ranks(a), rb = ranks(b);
  const double mean = double(a.size() - 1) / 2;
  double cov = 0, va = 0, vb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    cov += (ra[i] - mean) * (rb[i] - mean);
    va += (ra[i] - mean) * (ra[i] - mean);
    vb += (rb[i] - mean) * (rb[i] - mean);
  }
  return cov / std::sqrt(va * vb);
}

TEST(FamilySimilarity, ImageAndSpectrumDistancesAgree) {
  std::vector<std::vector<double>> looks(kMaterials), feels(kMaterials);
  std::vector<std::string> family(kMaterials);
  parallel_for(kMaterials, [&](std::size_t i) {
    const MaterialSpec spec = material_spec(int(i), 0);
    const HeightField surface = make_height_field(spec.surface, spec.seed);
    RendererOptions optics;
    optics.width = 320;
    optics.height = 240;
    optics.field_width_mm = 5;  // the 960-pixel sensor's resolution on a smaller crop
    looks[i] = image_features(GelSightRenderer(surface, optics));
    const HeightField tip = smoothed_for_tip(surface, kTipRadiusMm);
    feels[i] = spectrum_features(ProbeVibration(tip, spec));
    family[i] = spec.surface.family;
  });

  std::vector<double> look_distance, feel_distance;
  double within_look = 0, between_look = 0, within_feel = 0, between_feel = 0;
  int within = 0, between = 0;
  for (int a = 0; a < kMaterials; ++a)
    for (int b = a + 1; b < kMaterials; ++b) {
      const double dl = distance(looks[std::size_t(a)], looks[std::size_t(b)]);
      const double df = distance(feels[std::size_t(a)], feels[std::size_t(b)]);
      look_distance.push_back(dl);
      feel_distance.push_back(df);
      if (family[std::size_t(a)] == family[std::size_t(b)]) within_look += dl, within_feel += df, ++within;
      else between_look += dl, between_feel += df, ++between;
    }
  ASSERT_GT(within, 0);
  EXPECT_LT(within_look / within, between_look / between);
  EXPECT_LT(within_feel / within, between_feel / between);
  const double rho = spearman(look_distance, feel_distance);
  RecordProperty("spearman", std::to_string(rho));
  EXPECT_GT(rho, 0.0) << "rank correlation of image and spectrum distances over " << look_distance.size() << " pairs";
  std::printf("image/spectrum distance rank correlation over 20 materials: %.3f\n", rho);
}

}  // namespace
}  // namespace haptex::synth
