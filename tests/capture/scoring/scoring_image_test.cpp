#include <gtest/gtest.h>
#include <linux/videodev2.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "capture/device/fake_scene.hpp"
#include "capture/scoring/scoring_image.hpp"

namespace haptex::capture {
namespace {

cv::Mat gel(int width, int height) { return render_gel(width, height, 4, 0); }

TEST(ScoringImage, AveragesTwoFourOrEightPixelBlocksLeavingAtLeast160Columns) {
  EXPECT_EQ(scoring_size({320, 240}), cv::Size(160, 120));
  EXPECT_EQ(scoring_size({960, 720}), cv::Size(240, 180));
  EXPECT_EQ(scoring_size({3280, 2464}), cv::Size(410, 308));
  EXPECT_EQ(scoring_size({427, 320}), cv::Size(214, 160));
  EXPECT_EQ(scoring_size({100, 80}), cv::Size(100, 80));
  EXPECT_EQ(jpeg_reduction({3280, 2464}), 8);
  EXPECT_EQ(jpeg_reduction({960, 720}), 4);
  EXPECT_EQ(jpeg_reduction({320, 240}), 2);
}

TEST(ScoringImage, IsTheBlockMeanOfTheGreyImage) {
  const cv::Mat frame = gel(320, 240);
  const cv::Mat small = scoring_image(frame);
  ASSERT_EQ(small.type(), CV_32F);
  cv::Mat grey;
  cv::cvtColor(frame, grey, cv::COLOR_BGR2GRAY);
  const double block = cv::mean(grey(cv::Rect(100, 60, 2, 2)))[0];
  EXPECT_NEAR(small.at<float>(30, 50), block, 0.51);
}

TEST(ScoringImage, ReducedJpegDecodingAgreesWithTheFullPath) {
  for (const cv::Size size : {cv::Size(960, 720), cv::Size(640, 480)}) {
    const cv::Mat frame = gel(size.width, size.height);
    std::vector<std::uint8_t> jpeg;
    cv::imencode(".jpg", frame, jpeg, {cv::IMWRITE_JPEG_QUALITY, 95});
    const cv::Mat fast = scoring_image_from_jpeg(jpeg, size);
    const cv::Mat full = scoring_image(cv::imdecode(jpeg, cv::IMREAD_COLOR));
    ASSERT_EQ(fast.size(), full.size());
    cv::Mat d;
    cv::absdiff(fast, full, d);
    EXPECT_LT(cv::mean(d)[0], 1.0) << size;  // well under the 6-grey-level noise threshold
  }
}

TEST(ScoringImage, CorruptAndMisSizedPayloadsGiveNothing) {
  const cv::Mat frame = gel(320, 240);
  std::vector<std::uint8_t> jpeg;
  cv::imencode(".jpg", frame, jpeg);
  const std::vector<std::uint8_t> cut(jpeg.begin(), jpeg.begin() + 40);
  EXPECT_TRUE(scoring_image_from_jpeg(cut, {320, 240}).empty());
  EXPECT_TRUE(scoring_image_from_jpeg(jpeg, {640, 480}).empty()) << "a frame of another size";
  EXPECT_TRUE(scoring_image_from_yuyv(std::vector<std::uint8_t>(100), {320, 240}).empty());
}

TEST(ScoringImage, YuyvUsesTheLumaSamples) {
  const cv::Mat frame = gel(320, 240);
  const cv::Mat from_yuyv = scoring_image_from_yuyv(bgr_to_yuyv(frame), {320, 240});
  const cv::Mat from_bgr = scoring_image(frame);
  // Luma comes in video range (16..235) and is scored on the decoded frame's grey scale.
  cv::Mat d;
  cv::absdiff(from_yuyv, from_bgr, d);
  EXPECT_LT(cv::mean(d)[0], 1.0);
  std::vector<std::uint8_t> yuyv = bgr_to_yuyv(frame);
  cv::Mat luma;
  cv::extractChannel(cv::Mat(240, 320, CV_8UC2, yuyv.data()), luma, 0);
  double low = 0, high = 0;
  cv::minMaxLoc(luma, &low, &high);
  EXPECT_GE(low, 16.0);
  EXPECT_LE(high, 235.0);
}

}  // namespace
}  // namespace haptex::capture
