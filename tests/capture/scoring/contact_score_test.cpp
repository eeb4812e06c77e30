// The contact score ignores noise and uniform brightness changes and grows with a press.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "capture/scoring/contact_score.hpp"

namespace haptex::capture {
namespace {

cv::Mat flat_gel() {
  cv::Mat image(120, 160, CV_32F);
  for (int y = 0; y < image.rows; ++y)
    for (int x = 0; x < image.cols; ++x) image.at<float>(y, x) = 80.0f + 0.5f * float(x) + 0.3f * float(y);
  return image;
}

cv::Mat with_noise(const cv::Mat& image, double sigma, std::uint64_t seed) {
  cv::Mat noise(image.size(), CV_32F);
  cv::RNG rng(seed);
  rng.fill(noise, cv::RNG::NORMAL, 0, sigma);
  return image + noise;
}

cv::Mat pressed(const cv::Mat& image, float depth, int radius = 25) {
  cv::Mat out = image.clone();
  cv::circle(out, {80, 60}, radius, cv::Scalar(0), cv::FILLED);  // mask, filled below
  cv::Mat mask = cv::Mat::zeros(image.size(), CV_8U);
  cv::circle(mask, {80, 60}, radius, cv::Scalar(255), cv::FILLED);
  out = image.clone();
  cv::add(out, cv::Scalar(depth), out, mask);
  return out;
}

TEST(ContactScore, IsZeroForTheReferenceAndForNoiseBelowTheThreshold) {
  const cv::Mat ref = flat_gel();
  EXPECT_EQ(contact_score(ref, ref, 6), 0.0f);
  EXPECT_LT(contact_score(with_noise(ref, 1.0, 1), ref, 6), 1e-4f);
}

TEST(ContactScore, IgnoresUniformBrightnessDrift) {
  const cv::Mat ref = flat_gel();
  EXPECT_LT(contact_score(ref + 15.0, ref, 6), 1e-6f) << "an exposure step moves the median, not the score";
  EXPECT_GT(contact_score(pressed(ref, 20) + 15.0, ref, 6), 0.5f) << "the press still shows through the drift";
}

TEST(ContactScore, GrowsWithDepthAndArea) {
  const cv::Mat ref = flat_gel();
  const float shallow = contact_score(pressed(ref, 10), ref, 6);
  const float deep = contact_score(pressed(ref, 30), ref, 6);
  const float wide = contact_score(pressed(ref, 30, 40), ref, 6);
  EXPECT_GT(shallow, 0.0f);
  EXPECT_GT(deep, shallow);
  EXPECT_GT(wide, deep);
  // Mean excess over the threshold: a disc of radius 25 (1963 of 19200 pixels) 30 levels deep.
  EXPECT_NEAR(deep, (30 - 6) * 1963.0f / 19200.0f, 0.1f);
}

TEST(ContactReference, NoiseOfTheReferenceFramesRaisesThePixelThreshold) {
  const cv::Mat gel = flat_gel();
  std::vector<cv::Mat> quiet, noisy;
  for (int i = 0; i < 10; ++i) {
    quiet.push_back(with_noise(gel, 0.5, 10 + std::uint64_t(i)));
    noisy.push_back(with_noise(gel, 3.0, 30 + std::uint64_t(i)));
  }
  const ContactReference q = ContactReference::from_frames(quiet);
  const ContactReference n = ContactReference::from_frames(noisy);
  EXPECT_NEAR(q.noise(), 0.5f, 0.05f);
  EXPECT_FLOAT_EQ(q.pixel_threshold(), 6.0f) << "the floor";
  EXPECT_NEAR(n.noise(), 3.0f, 0.2f);
  EXPECT_NEAR(n.pixel_threshold(), 12.0f, 0.8f) << "4 sigma";
  EXPECT_FLOAT_EQ(q.trigger(), 0.25f);
  EXPECT_FLOAT_EQ(q.release(), 0.125f);
  // A fresh noisy frame (not among the reference frames) stays far below the trigger.
  EXPECT_LT(n.score(with_noise(gel, 3.0, 99)), n.trigger() / 10);
  EXPECT_GT(n.score(pressed(gel, 40)), n.trigger() * 4);
}

TEST(ContactReference, AGivenImageUsesTheFloors) {
  const ContactReference r = ContactReference::from_image(flat_gel());
  EXPECT_EQ(r.noise(), 0.0f);
  EXPECT_FLOAT_EQ(r.pixel_threshold(), 6.0f);
  EXPECT_FLOAT_EQ(r.trigger(), 0.25f);
}

}  // namespace
}  // namespace haptex::capture
