#include "dataset/decode_image.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace haptex::dataset {
namespace {

using Bytes = std::vector<std::uint8_t>;

// A press-like picture: smooth shading, fine texture and sharp edges, sides no multiple of 8 or 16.
cv::Mat picture() {
  cv::Mat image(250, 333, CV_8UC3);
  cv::RNG rng(7);
  rng.fill(image, cv::RNG::UNIFORM, 0, 256);
  cv::GaussianBlur(image, image, {0, 0}, 1.5);
  cv::circle(image, {160, 120}, 70, {30, 200, 90}, 5);
  return image;
}

Bytes encode(const cv::Mat& image, const std::string& ext) {
  Bytes bytes;
  EXPECT_TRUE(cv::imencode(ext, image, bytes, {cv::IMWRITE_JPEG_QUALITY, 90}));
  return bytes;
}

// What the call wrote to stderr (file descriptor 2), which a library here must leave alone.
std::string stderr_of(const std::function<void()>& call) {
  std::fflush(stderr);
  std::FILE* capture = std::tmpfile();
  const int saved = dup(2);
  dup2(fileno(capture), 2);
  call();
  std::fflush(stderr);
  dup2(saved, 2);
  close(saved);
  std::string text(std::size_t(std::ftell(capture)), '\0');
  std::rewind(capture);
  text.resize(std::fread(text.data(), 1, text.size(), capture));
  std::fclose(capture);
  return text;
}

bool same(const cv::Mat& a, const cv::Mat& b) {
  return a.size() == b.size() && a.type() == b.type() && cv::norm(a, b, cv::NORM_INF) == 0;
}

TEST(DecodeImage, JpegPixelsAreOpenCvsBitForBit) {
  const Bytes jpeg = encode(picture(), ".jpg");
  EXPECT_TRUE(same(decode_jpeg(jpeg), cv::imdecode(jpeg, cv::IMREAD_COLOR)));
  EXPECT_TRUE(same(decode_image(jpeg), cv::imdecode(jpeg, cv::IMREAD_COLOR)));
  EXPECT_TRUE(same(decode_jpeg(jpeg, DecodedColour::grey), cv::imdecode(jpeg, cv::IMREAD_GRAYSCALE)));
  const std::pair<int, int> reduced[] = {{2, cv::IMREAD_REDUCED_GRAYSCALE_2}, {4, cv::IMREAD_REDUCED_GRAYSCALE_4}, {8, cv::IMREAD_REDUCED_GRAYSCALE_8}};
  for (const auto& [r, flag] : reduced) {
    SCOPED_TRACE(r);
    const cv::Mat ours = decode_jpeg(jpeg, DecodedColour::grey, r);
    EXPECT_EQ(ours.size(), cv::Size((333 + r - 1) / r, (250 + r - 1) / r));
    EXPECT_TRUE(same(ours, cv::imdecode(jpeg, flag)));
  }
  EXPECT_TRUE(decode_jpeg(jpeg, DecodedColour::grey, 3).empty());
}

TEST(DecodeImage, PngPixelsAreOpenCvs) {
  const Bytes png = encode(picture(), ".png");
  EXPECT_TRUE(same(decode_image(png), picture()));
  EXPECT_TRUE(decode_jpeg(png).empty());
}

// A webcam's "extraneous bytes before marker 0xd9": the frame decodes, the warning is counted, and
// nothing reaches stderr, where cv::imdecode prints "Corrupt JPEG data: 64 extraneous bytes ...".
TEST(DecodeImage, JpegWarningsAreCountedNotPrinted) {
  const Bytes clean = encode(picture(), ".jpg");
  Bytes noisy(clean.begin(), clean.end() - 2);
  noisy.insert(noisy.end(), 64, 0x12);
  noisy.insert(noisy.end(), {0xFF, 0xD9});
  EXPECT_NE(stderr_of([&] { cv::imdecode(noisy, cv::IMREAD_COLOR); }), "");
  cv::Mat image;
  int warnings = 0;
  EXPECT_EQ(stderr_of([&] { image = decode_jpeg(noisy, DecodedColour::bgr, 1, &warnings); }), "");
  EXPECT_EQ(warnings, 1);
  EXPECT_TRUE(same(image, decode_jpeg(clean)));
  int none = -1;
  decode_jpeg(clean, DecodedColour::bgr, 1, &none);
  EXPECT_EQ(none, 0);
}

TEST(DecodeImage, DamagedImagesAreEmptyAndQuiet) {
  const Bytes jpeg = encode(picture(), ".jpg");
  const Bytes png = encode(picture(), ".png");
  Bytes garbage = {0xFF, 0xD8};
  for (int i = 0; i < 500; ++i) garbage.push_back(std::uint8_t(i * 37 + 11));
  garbage.insert(garbage.end(), {0xFF, 0xD9});
  Bytes huge = jpeg;  // the frame header (SOF0) states 60000 x 60000 pixels
  for (std::size_t i = 2; i + 8 < huge.size(); ++i)
    if (huge[i] == 0xFF && huge[i + 1] == 0xC0) {
      huge[i + 5] = huge[i + 7] = 0xEA;
      huge[i + 6] = huge[i + 8] = 0x60;
      break;
    }
  const std::vector<std::pair<std::string, Bytes>> cases = {
      {"cut-off JPEG", Bytes(jpeg.begin(), jpeg.begin() + long(jpeg.size() / 2))},
      {"cut-off PNG", Bytes(png.begin(), png.begin() + long(png.size() / 2))},
      {"noise between SOI and EOI", garbage},
      {"60000 x 60000 JPEG", huge},
      {"empty", {}},
      {"text", {'h', 'e', 'l', 'l', 'o'}},
  };
  for (const auto& [name, bytes] : cases) {
    SCOPED_TRACE(name);
    cv::Mat image;
    EXPECT_EQ(stderr_of([&] { image = decode_image(bytes); }), "");
    EXPECT_TRUE(image.empty());
  }
}

}  // namespace
}  // namespace haptex::dataset
