// The contact score and press segmentation on real GelSight-type captures (../shared/data,
// docs/capture.md): skipped when that folder is absent. The data is never copied into the repository.
#include <gtest/gtest.h>

#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "capture/extraction/peak_frames.hpp"
#include "capture/scoring/contact_score.hpp"
#include "capture/scoring/scoring_image.hpp"
#include "tests/support/npy.hpp"

namespace haptex::capture {
namespace {

namespace fs = std::filesystem;

std::string gelsight_data(const std::string& folder) {
  const std::string root = haptex::test::shared_data_dir();
  if (root.empty()) return {};
  const fs::path p = fs::path(root) / "gelsight" / folder;
  return fs::is_directory(p) ? p.string() : std::string();
}

cv::Mat load(const std::string& path) {
  cv::Mat image = cv::imread(path, cv::IMREAD_COLOR);
  EXPECT_FALSE(image.empty()) << path;
  return image;
}

// The image plus Gaussian noise of `sigma` grey levels per pixel and channel, as a sensor adds.
cv::Mat with_sensor_noise(const cv::Mat& image, double sigma, std::uint64_t seed) {
  cv::Mat noise(image.size(), CV_32FC3), noisy;
  cv::RNG rng(seed);
  rng.fill(noise, cv::RNG::NORMAL, 0, sigma);
  image.convertTo(noisy, CV_32FC3);
  noisy += noise;
  noisy.convertTo(noisy, CV_8UC3);
  return noisy;
}

TEST(RealCaptures, MiniExampleVideo) {
  const std::string dir = gelsight_data("gsrobotics_gsmini_markers");
  if (dir.empty()) GTEST_SKIP() << "../shared/data/gelsight/gsrobotics_gsmini_markers is absent";
  auto source = open_video(dir + "/mini_example.avi");
  const SourceScores scores = score_source(*source, {});
  ASSERT_EQ(scores.scores.size(), 219u);
  const auto plans = plan_presses(scores.scores, scores.contact->segmenter({}), 12, 10);
  ASSERT_FALSE(plans.empty());
  for (const auto& p : plans) EXPECT_GT(p.contact.first, 50) << "no press in frames 0 to 50";
  const auto strongest = std::max_element(plans.begin(), plans.end(), [](const PressPlan& a, const PressPlan& b) {
    return a.contact.peak_score < b.contact.peak_score;
  });
  EXPECT_NEAR(double(strongest->contact.peak), 98.0, 3.0);
  // The presses docs/capture.md lists.
  ASSERT_EQ(plans.size(), 3u);
  EXPECT_EQ(plans[0].contact.first, 57);
  EXPECT_EQ(plans[1].contact.first, 90);
  EXPECT_EQ(plans[2].contact.first, 160);
  for (const auto& p : plans) EXPECT_EQ(p.frame_indices.size(), 12u);
}

TEST(RealCaptures, GsSdkPressesAgainstTheirBackground) {
  const std::string dir = gelsight_data("gs_sdk_gsmini");
  if (dir.empty()) GTEST_SKIP() << "../shared/data/gelsight/gs_sdk_gsmini is absent";
  const cv::Mat background = load(dir + "/background.png");
  const ContactReference reference = ContactReference::from_image(scoring_image(background));
  for (const char* press : {"bead", "key", "seed"}) {
    const float score = reference.score(scoring_image(load(dir + "/" + press + ".png")));
    EXPECT_GT(score, 2 * reference.trigger()) << press;
  }
  for (std::uint64_t seed = 1; seed <= 3; ++seed)
    for (double sigma : {2.0, 4.0}) {
      const float score = reference.score(scoring_image(with_sensor_noise(background, sigma, seed)));
      EXPECT_LT(score, reference.trigger() / 4) << "background + noise " << sigma;
    }
}

TEST(RealCaptures, GelSlimBallPressesAgainstTheirReference) {
  const std::string dir = gelsight_data("gelslim4");
  if (dir.empty()) GTEST_SKIP() << "../shared/data/gelsight/gelslim4 is absent";
  const cv::Mat ref = load(dir + "/ref.jpg");
  const ContactReference reference = ContactReference::from_image(scoring_image(ref));
  int samples = 0, detected = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("sample_", 0) != 0) continue;
    ++samples;
    detected += reference.score(scoring_image(load(entry.path().string()))) > reference.trigger();
  }
  ASSERT_GE(samples, 38);
  EXPECT_GE(detected, std::min(samples, 38));
  EXPECT_EQ(detected, samples) << "every ball press is seen";
  for (std::uint64_t seed = 1; seed <= 3; ++seed)
    for (double sigma : {2.0, 4.0}) {
      const float score = reference.score(scoring_image(with_sensor_noise(ref, sigma, seed)));
      EXPECT_LT(score, reference.trigger() / 4) << "ref + noise " << sigma;
    }
}

}  // namespace
}  // namespace haptex::capture
