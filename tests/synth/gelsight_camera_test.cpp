#include "synth/gelsight_camera.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"

namespace haptex::synth {
namespace {

cv::Mat constant_radiance(int width, int height, float grey) {
  return cv::Mat(height, width, CV_32FC3, cv::Scalar(grey, grey, grey));
}

TEST(GelSightCamera, NoiseIsAboutOneGreyLevelAndSeeded) {
  const GelSightCamera camera({320, 240, 1.0, 0.0});
  const cv::Mat frame = camera.expose(constant_radiance(320, 240, 100.4f), 1.0, 7);
  ASSERT_EQ(frame.type(), CV_8UC3);
  ASSERT_EQ(frame.size(), cv::Size(320, 240));
  cv::Scalar mean, deviation;
  cv::meanStdDev(frame.reshape(1), mean, deviation);
  EXPECT_NEAR(mean[0], 100.4, 0.05);  // noise without bias: rounding averages out
  EXPECT_NEAR(deviation[0], 1.0, 0.1);

  EXPECT_EQ(cv::norm(frame, camera.expose(constant_radiance(320, 240, 100.4f), 1.0, 7), cv::NORM_INF), 0);
  EXPECT_GT(cv::norm(frame, camera.expose(constant_radiance(320, 240, 100.4f), 1.0, 8), cv::NORM_L1), 0);
}

TEST(GelSightCamera, ExposureGainScalesTheImage) {
  const GelSightCamera camera({320, 240, 1.0, 0.0});
  const cv::Mat radiance = constant_radiance(320, 240, 200);
  const double base = cv::mean(camera.expose(radiance, 1.0, 1))[1];
  const double drifted = cv::mean(camera.expose(radiance, 1.003, 1))[1];
  EXPECT_NEAR(drifted - base, 0.6, 0.05);  // 0.3 % of 200 grey levels
}

TEST(GelSightCamera, VignettingDarkensTheCorners) {
  const GelSightCamera camera({320, 240, 0.0, 0.2});
  const cv::Mat frame = camera.expose(constant_radiance(320, 240, 150), 1.0, 1);
  EXPECT_EQ(frame.at<cv::Vec3b>(120, 160)[0], 150);
  EXPECT_NEAR(frame.at<cv::Vec3b>(0, 0)[0], 120, 1);  // 20 % lost in the corner
  EXPECT_GT(frame.at<cv::Vec3b>(120, 100)[0], frame.at<cv::Vec3b>(120, 20)[0]);
}

TEST(GelSightCamera, ClipsToEightBits) {
  const GelSightCamera camera({64, 48, 3.0, 0.0});
  cv::Mat radiance = constant_radiance(64, 48, 300);
  radiance(cv::Rect(0, 0, 32, 48)).setTo(cv::Scalar(-20, -20, -20));
  const cv::Mat frame = camera.expose(radiance, 1.0, 3);
  double lo = 0, hi = 0;
  cv::minMaxLoc(frame.reshape(1), &lo, &hi);
  EXPECT_EQ(lo, 0);
  EXPECT_EQ(hi, 255);
}

TEST(GelSightCamera, RefusesAWrongImage) {
  const GelSightCamera camera({64, 48, 1.0, 0.2});
  EXPECT_THROW(camera.expose(constant_radiance(48, 64, 1), 1.0, 1), Error);
  EXPECT_THROW(camera.expose(cv::Mat(48, 64, CV_8UC3), 1.0, 1), Error);
  EXPECT_THROW(GelSightCamera({4, 4, 1.0, 0.2}), Error);
}

}  // namespace
}  // namespace haptex::synth
