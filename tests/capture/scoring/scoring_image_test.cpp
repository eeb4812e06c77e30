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

// Every block, for blocks of 2, 4 and 8 and widths whose block count is no multiple of 4 (the SIMD
// path's tail): exactly the mean of OpenCV's grey image over the block.
TEST(ScoringImage, IsTheBlockMeanOfTheGreyImage) {
  for (const cv::Size size : {cv::Size(320, 240), cv::Size(332, 240), cv::Size(968, 720), cv::Size(1288, 968), cv::Size(3280, 2464)}) {
    cv::Mat frame(size, CV_8UC3);
    cv::randu(frame, 0, 256);
    const cv::Mat small = scoring_image(frame);
    ASSERT_EQ(small.type(), CV_32F);
    const int r = jpeg_reduction(size);
    ASSERT_EQ(small.size(), cv::Size(size.width / r, size.height / r)) << size;
    cv::Mat grey;
    cv::cvtColor(frame, grey, cv::COLOR_BGR2GRAY);
    for (int j = 0; j < small.rows; ++j)
      for (int i = 0; i < small.cols; ++i)
        ASSERT_FLOAT_EQ(small.at<float>(j, i), float(cv::sum(grey(cv::Rect(r * i, r * j, r, r)))[0] / (r * r)))
            << size << " r " << r << " block " << i << ", " << j;
  }
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
