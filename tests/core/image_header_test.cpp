#include "core/image_header.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>
#include <vector>

namespace haptex {
namespace {

std::vector<std::uint8_t> encoded(const char* ext) {
  cv::Mat image(48, 64, CV_8UC3);
  cv::randu(image, 0, 255);
  std::vector<std::uint8_t> bytes;
  EXPECT_TRUE(cv::imencode(ext, image, bytes));
  return bytes;
}

TEST(ImageHeader, SizesFromTheHeaderInMemory) {
  for (const char* ext : {".png", ".jpg"}) {
    const auto size = image_header_size(encoded(ext));
    ASSERT_TRUE(size) << ext;
    EXPECT_EQ(size->width, 64u) << ext;
    EXPECT_EQ(size->height, 48u) << ext;
  }
  EXPECT_FALSE(image_header_size(std::vector<std::uint8_t>{'G', 'I', 'F', '8'}));
}

// Whole images pass; cut anywhere, or with one byte changed inside a chunk, a PNG does not.
TEST(ImageHeader, WholePngAndJpegAreToldFromDamagedOnes) {
  const std::vector<std::uint8_t> png = encoded(".png"), jpeg = encoded(".jpg");
  EXPECT_TRUE(is_complete_png(png));
  EXPECT_TRUE(is_complete_jpeg(jpeg));
  for (std::size_t keep : {std::size_t(0), std::size_t(8), std::size_t(33), png.size() / 2, png.size() - 1}) {
    EXPECT_FALSE(is_complete_png(std::vector<std::uint8_t>(png.begin(), png.begin() + std::ptrdiff_t(keep)))) << keep;
    EXPECT_FALSE(is_complete_jpeg(std::vector<std::uint8_t>(jpeg.begin(), jpeg.begin() + std::ptrdiff_t(std::min(keep, jpeg.size() / 2)))));
  }
  std::vector<std::uint8_t> flipped = png;
  flipped[png.size() / 2] ^= 0x10;
  EXPECT_FALSE(is_complete_png(flipped)) << "a chunk's CRC no longer holds";
  std::vector<std::uint8_t> longer = png;
  longer.push_back(0);
  EXPECT_FALSE(is_complete_png(longer)) << "bytes after IEND";
  EXPECT_FALSE(is_complete_png(jpeg));
}

}  // namespace
}  // namespace haptex
