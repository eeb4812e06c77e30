#include <gtest/gtest.h>

#include "core/error.hpp"
#include "predict/augmentation.hpp"

namespace haptex::predict {
namespace {

// A 2 x 3 image with distinct pixels, so every symmetry gives a different image.
cv::Mat asymmetric() { return (cv::Mat_<std::uint8_t>(2, 3) << 1, 2, 3, 4, 5, 6); }

bool same(const cv::Mat& a, const cv::Mat& b) {
  return a.size() == b.size() && a.type() == b.type() && cv::countNonZero(a != b) == 0;
}

TEST(Augmentation, EightDistinctVariantsOfWhichTheFirstIsTheImage) {
  const auto all = all_augmentations(asymmetric());
  ASSERT_EQ(all.size(), 8u);
  EXPECT_TRUE(same(all[0], asymmetric()));
  for (std::size_t i = 0; i < all.size(); ++i)
    for (std::size_t j = i + 1; j < all.size(); ++j) EXPECT_FALSE(same(all[i], all[j])) << i << " vs " << j;
}

TEST(Augmentation, RotationsAndMirrorAsDocumented) {
  const cv::Mat image = asymmetric();
  const cv::Mat ccw = augment(image, 1);  // 90 degrees counter-clockwise
  EXPECT_TRUE(same(ccw, (cv::Mat_<std::uint8_t>(3, 2) << 3, 6, 2, 5, 1, 4)));
  EXPECT_TRUE(same(augment(image, 2), (cv::Mat_<std::uint8_t>(2, 3) << 6, 5, 4, 3, 2, 1)));
  EXPECT_TRUE(same(augment(image, 4), (cv::Mat_<std::uint8_t>(2, 3) << 3, 2, 1, 6, 5, 4)));
  // Four quarter turns are the identity; mirroring twice too.
  cv::Mat turned = image.clone();
  for (int i = 0; i < 4; ++i) turned = augment(turned, 1);
  EXPECT_TRUE(same(turned, image));
  EXPECT_TRUE(same(augment(augment(image, 4), 4), image));
}

TEST(Augmentation, KeepsColourImagesAndRefusesUnknownVariants) {
  cv::Mat colour(4, 6, CV_8UC3, cv::Scalar(1, 2, 3));
  EXPECT_EQ(augment(colour, 3).size(), cv::Size(4, 6));
  EXPECT_EQ(augment(colour, 3).type(), CV_8UC3);
  EXPECT_THROW(augment(colour, 8), Error);
}

}  // namespace
}  // namespace haptex::predict
