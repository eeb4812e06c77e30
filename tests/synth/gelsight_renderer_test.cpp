#include "synth/gelsight_renderer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"
#include "tests/synth/press_frames.hpp"

namespace haptex::synth {
namespace {

// 240 x 180 pixels over 3.75 x 2.8 mm: the default's 64 px/mm on a small image.
RendererOptions small_view() {
  RendererOptions options;
  options.width = 240;
  options.height = 180;
  options.field_width_mm = 3.75;
  return options;
}

HeightField rough_field(double rms_um, double correlation_mm = 0.1, std::uint64_t seed = 5) {
  SurfaceRecipe recipe;
  recipe.rms_um = rms_um;
  recipe.correlation_mm = correlation_mm;
  return make_height_field(recipe, seed, 256, 4.0);
}

// One Gaussian bump, 40 um high and 0.3 mm wide, in the middle of a flat 4 mm field.
HeightField bump_field() {
  HeightField field;
  field.n = 256;
  field.period_mm = 4.0;
  field.height_mm.resize(256 * 256);
  for (int y = 0; y < 256; ++y)
    for (int x = 0; x < 256; ++x) {
      const double r2 = (std::pow(x - 128, 2) + std::pow(y - 128, 2)) * std::pow(field.pixel_mm(), 2);
      field.height_mm[std::size_t(y * 256 + x)] = float(0.04 * std::exp(-r2 / (2 * 0.3 * 0.3)));
    }
  return field;
}

cv::Mat grey_difference(const cv::Mat& frame, const cv::Mat& reference) {
  cv::Mat a, b;
  cv::cvtColor(frame, a, cv::COLOR_BGR2GRAY);
  cv::cvtColor(reference, b, cv::COLOR_BGR2GRAY);
  a.convertTo(a, CV_32F);
  b.convertTo(b, CV_32F);
  return a - b;
}

// The share of a difference image's energy in detail finer than ~2 pixels (what a 2-pixel Gaussian
// blur removes).
double fine_detail_share(const cv::Mat& difference) {
  cv::Mat coarse;
  cv::GaussianBlur(difference, coarse, cv::Size(0, 0), 2.0);
  const double total = cv::norm(difference, cv::NORM_L2SQR);
  return total > 0 ? cv::norm(difference - coarse, cv::NORM_L2SQR) / total : 0;
}

TEST(GelSightRenderer, SurfaceUnderSamplesThePeriodicField) {
  const HeightField field = rough_field(10);
  RendererOptions options = small_view();
  options.gel_radius_mm = 0;
  const GelSightRenderer renderer(field, options);
  const PressPose pose{3.3, 3.9, 0, 0};  // the view runs over the field's edges: it must wrap around
  const cv::Mat surface = renderer.surface_under(pose);
  ASSERT_EQ(surface.type(), CV_32F);
  ASSERT_EQ(surface.size(), cv::Size(240, 180));
  double highest = 0;
  cv::minMaxLoc(surface, nullptr, &highest);
  EXPECT_EQ(highest, 0);
  // Up to the constant shift, the surface is the field sampled (bilinearly, as warpAffine does) at
  // each pixel's position, wrapping around the field's edges.
  const auto bilinear = [&](double x_mm, double y_mm) {
    const double fx = x_mm / field.pixel_mm(), fy = y_mm / field.pixel_mm();
    const int ix = int(std::floor(fx)), iy = int(std::floor(fy));
    const double tx = fx - ix, ty = fy - iy;
    return (1 - ty) * ((1 - tx) * field.at(ix, iy) + tx * field.at(ix + 1, iy)) +
           ty * ((1 - tx) * field.at(ix, iy + 1) + tx * field.at(ix + 1, iy + 1));
  };
  const double shift = surface.at<float>(0, 0) - bilinear(pose.x_mm, pose.y_mm);
  for (auto [u, v] : {std::pair{17, 3}, {100, 90}, {239, 179}, {50, 170}}) {
    const double expected = bilinear(pose.x_mm + u * renderer.pixel_mm(), pose.y_mm + v * renderer.pixel_mm());
    // 1e-4 mm is 1 % of the RMS height: warpAffine interpolates at 1/32-pixel steps.
    EXPECT_NEAR(surface.at<float>(v, u) - shift, expected, 1e-4) << u << ", " << v;
  }
}

TEST(GelSightRenderer, TiltAndDomeDecideWhereContactStarts) {
  HeightField flat;
  flat.n = 16;
  flat.period_mm = 4.0;
  flat.height_mm.assign(256, 0.0f);
  RendererOptions options = small_view();
  options.gel_radius_mm = 100;
  const GelSightRenderer renderer(flat, options);
  cv::Point highest;
  cv::minMaxLoc(renderer.surface_under({0, 0, 0, 0}), nullptr, nullptr, nullptr, &highest);
  EXPECT_NEAR(highest.x, 120, 1);  // a dome touches first at its apex
  EXPECT_NEAR(highest.y, 90, 1);
  cv::minMaxLoc(renderer.surface_under({0, 0, 0.01, 0}), nullptr, nullptr, nullptr, &highest);
  EXPECT_NEAR(highest.x, 120 + 0.01 * 100 / renderer.pixel_mm(), 1);  // tilt moves it by R x slope
}

TEST(GelSightRenderer, NoContactIsTheUntouchedGel) {
  const GelSightRenderer renderer(rough_field(20), small_view());
  const PressPose pose{1, 1, 0.003, 0.001};
  const cv::Mat quiet_a = renderer.render(0, pose, 1.0, 1), quiet_b = renderer.render(0, pose, 1.0, 2);
  EXPECT_LT(test::mean_abs_difference(quiet_a, quiet_b), 1.5);  // noise only
  // The untouched gel is the three lights on the skin: grey-ish, a little brighter in the middle.
  const cv::Scalar centre = cv::mean(quiet_a(cv::Rect(100, 70, 40, 40)));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(centre[c], flat_gel_colour()[c], 4);
  EXPECT_GT(cv::mean(quiet_a(cv::Rect(100, 70, 40, 40)))[1], cv::mean(quiet_a(cv::Rect(0, 0, 20, 20)))[1] + 5);

  const cv::Mat pressed = renderer.render(0.1, pose, 1.0, 3);
  EXPECT_GT(test::mean_abs_difference(pressed, quiet_a), 3.0);
}

TEST(GelSightRenderer, EachLightColoursTheSlopesFacingIt) {
  RendererOptions options = small_view();
  options.noise_grey = 0;
  options.vignetting = 0;
  options.gel_radius_mm = 0;
  const GelSightRenderer renderer(bump_field(), options);
  // The bump sits at (2, 2) mm: put it in the middle of the view and press past its height.
  const PressPose pose{2 - 120 * renderer.pixel_mm(), 2 - 90 * renderer.pixel_mm(), 0, 0};
  const cv::Mat frame = renderer.render(0.08, pose, 1.0, 0);
  const int side = 20;  // pixels from the bump's centre, on its flank
  const cv::Vec3b below = frame.at<cv::Vec3b>(90 + side, 120), above = frame.at<cv::Vec3b>(90 - side, 120);
  // The red light shines from +y (azimuth 90 degrees): the flank below the centre faces it.
  EXPECT_GT(int(below[2]), int(above[2]) + 10);
  // Green (210 degrees) and blue (330 degrees) come from -y: the flank above the centre is theirs.
  EXPECT_GT(int(above[1]), int(below[1]) + 5);
  EXPECT_GT(int(above[0]), int(below[0]) + 5);
  // Blue from +x (330 degrees), green from -x (210 degrees).
  const cv::Vec3b right = frame.at<cv::Vec3b>(90, 120 + side), left = frame.at<cv::Vec3b>(90, 120 - side);
  EXPECT_GT(int(right[0]), int(left[0]) + 10);
  EXPECT_GT(int(left[1]), int(right[1]) + 10);
}

TEST(GelSightRenderer, RougherSurfaceGivesStrongerContrast) {
  RendererOptions options = small_view();
  const PressPose pose{0.5, 0.5, 0.002, 0};
  double contrast[2];
  for (int k = 0; k < 2; ++k) {
    const GelSightRenderer renderer(rough_field(k == 0 ? 3 : 12), options);
    const cv::Mat difference = grey_difference(renderer.render(0.12, pose, 1.0, 11), renderer.render(0, pose, 1.0, 12));
    cv::Scalar mean, deviation;
    cv::meanStdDev(difference, mean, deviation);
    contrast[k] = deviation[0];
  }
  EXPECT_GT(contrast[1], 2 * contrast[0]) << "smooth " << contrast[0] << ", rough " << contrast[1];
}

TEST(GelSightRenderer, ShallowContactSmoothsFineDetailMore) {
  RendererOptions options = small_view();
  options.noise_grey = 0;  // noise is all fine detail: it would blur the comparison
  options.gel_radius_mm = 0;
  const GelSightRenderer renderer(rough_field(10), options);
  EXPECT_GT(renderer.smoothing_mm(0.01), 2 * renderer.smoothing_mm(0.3));
  const PressPose pose{0.7, 0.2, 0, 0};
  const cv::Mat reference = renderer.render(0, pose, 1.0, 0);
  // At 0.05 mm nearly all of this surface touches the gel (at less, the few contact spots are too
  // faint for 8-bit frames: rounding would be their finest detail).
  const double shallow = fine_detail_share(grey_difference(renderer.render(0.05, pose, 1.0, 0), reference));
  const double deep = fine_detail_share(grey_difference(renderer.render(0.3, pose, 1.0, 0), reference));
  EXPECT_LT(shallow, 0.5 * deep) << "shallow " << shallow << ", deep " << deep;
}

TEST(GelSightRenderer, DeterministicForANoiseSeed) {
  const GelSightRenderer renderer(rough_field(8), small_view());
  const PressPose pose{1.5, 2.5, 0.002, -0.003};
  EXPECT_EQ(cv::norm(renderer.render(0.1, pose, 1.001, 9), renderer.render(0.1, pose, 1.001, 9), cv::NORM_INF), 0);
}

TEST(GelSightRenderer, RefusesBadInput) {
  EXPECT_THROW(GelSightRenderer(HeightField{}, small_view()), Error);
  RendererOptions bad = small_view();
  bad.smoothing_shallow_mm = 0.01;  // narrower than the deep smoothing
  EXPECT_THROW(GelSightRenderer(rough_field(1), bad), Error);
  const GelSightRenderer renderer(rough_field(1), small_view());
  EXPECT_THROW(renderer.shade(cv::Mat::zeros(10, 10, CV_32F), 0.1), Error);
}

}  // namespace
}  // namespace haptex::synth
