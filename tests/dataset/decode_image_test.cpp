#include "dataset/decode_image.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "tests/support/temp_dir.hpp"

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

const std::uint8_t kStartOfScan[] = {0xFF, 0xDA};

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
  JpegReport report;
  EXPECT_EQ(stderr_of([&] { image = decode_jpeg(noisy, DecodedColour::bgr, 1, &report); }), "");
  EXPECT_EQ(report.warnings, 1);
  EXPECT_EQ(report.damage, "");
  EXPECT_NE(report.first_warning.find("extraneous bytes"), std::string::npos) << report.first_warning;
  EXPECT_TRUE(same(image, decode_jpeg(clean)));
  JpegReport none{-1, "x", "y"};
  decode_jpeg(clean, DecodedColour::bgr, 1, &none);
  EXPECT_EQ(none.warnings, 0);
  EXPECT_EQ(none.damage, "");
  EXPECT_EQ(none.first_warning, "");
}

// Coded data changed in transfer (every 97th byte after the scan header flipped; the end marker
// kept): libjpeg meets bits that are no Huffman code, or a marker where none belongs, and would draw
// garbage. Refused, saying what libjpeg found, at every reduction, without a word on stderr.
TEST(DecodeImage, DamagedCodedDataIsRefusedNamingTheDamage) {
  const Bytes clean = encode(picture(), ".jpg");
  Bytes damaged = clean;
  const auto scan = std::search(damaged.begin(), damaged.end(), std::begin(kStartOfScan), std::end(kStartOfScan));
  ASSERT_NE(scan, damaged.end());
  for (std::size_t i = std::size_t(scan - damaged.begin()) + 20; i + 2 < damaged.size(); i += 97) damaged[i] ^= 0x5A;
  EXPECT_NE(stderr_of([&] { cv::imdecode(damaged, cv::IMREAD_COLOR); }), "");
  for (int reduction : {1, 8}) {
    JpegReport report;
    cv::Mat image;
    EXPECT_EQ(stderr_of([&] { image = decode_jpeg(damaged, DecodedColour::grey, reduction, &report); }), "");
    EXPECT_TRUE(image.empty());
    EXPECT_NE(report.damage, "");
  }
  EXPECT_TRUE(decode_image(damaged).empty());
}

// A 16 x 8 CMYK JPEG: PIL's Image.new("CMYK", (16, 8), (10, 200, 30, 5)).save(f, "JPEG", quality=50).
const Bytes kCmykJpeg = {
    0xFF, 0xD8, 0xFF, 0xEE, 0x00, 0x0E, 0x41, 0x64, 0x6F, 0x62, 0x65, 0x00, 0x64, 0x00, 0x00, 0x00, 0x00,
    0x00, 0xFF, 0xDB, 0x00, 0x43, 0x00, 0x10, 0x0B, 0x0C, 0x0E, 0x0C, 0x0A, 0x10, 0x0E, 0x0D, 0x0E, 0x12,
    0x11, 0x10, 0x13, 0x18, 0x28, 0x1A, 0x18, 0x16, 0x16, 0x18, 0x31, 0x23, 0x25, 0x1D, 0x28, 0x3A, 0x33,
    0x3D, 0x3C, 0x39, 0x33, 0x38, 0x37, 0x40, 0x48, 0x5C, 0x4E, 0x40, 0x44, 0x57, 0x45, 0x37, 0x38, 0x50,
    0x6D, 0x51, 0x57, 0x5F, 0x62, 0x67, 0x68, 0x67, 0x3E, 0x4D, 0x71, 0x79, 0x70, 0x64, 0x78, 0x5C, 0x65,
    0x67, 0x63, 0xFF, 0xC0, 0x00, 0x14, 0x08, 0x00, 0x08, 0x00, 0x10, 0x04, 0x43, 0x11, 0x00, 0x4D, 0x11,
    0x00, 0x59, 0x11, 0x00, 0x4B, 0x11, 0x00, 0xFF, 0xC4, 0x00, 0x1F, 0x00, 0x00, 0x01, 0x05, 0x01, 0x01,
    0x01, 0x01, 0x01, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x01, 0x02, 0x03, 0x04, 0x05,
    0x06, 0x07, 0x08, 0x09, 0x0A, 0x0B, 0xFF, 0xC4, 0x00, 0xB5, 0x10, 0x00, 0x02, 0x01, 0x03, 0x03, 0x02,
    0x04, 0x03, 0x05, 0x05, 0x04, 0x04, 0x00, 0x00, 0x01, 0x7D, 0x01, 0x02, 0x03, 0x00, 0x04, 0x11, 0x05,
    0x12, 0x21, 0x31, 0x41, 0x06, 0x13, 0x51, 0x61, 0x07, 0x22, 0x71, 0x14, 0x32, 0x81, 0x91, 0xA1, 0x08,
    0x23, 0x42, 0xB1, 0xC1, 0x15, 0x52, 0xD1, 0xF0, 0x24, 0x33, 0x62, 0x72, 0x82, 0x09, 0x0A, 0x16, 0x17,
    0x18, 0x19, 0x1A, 0x25, 0x26, 0x27, 0x28, 0x29, 0x2A, 0x34, 0x35, 0x36, 0x37, 0x38, 0x39, 0x3A, 0x43,
    0x44, 0x45, 0x46, 0x47, 0x48, 0x49, 0x4A, 0x53, 0x54, 0x55, 0x56, 0x57, 0x58, 0x59, 0x5A, 0x63, 0x64,
    0x65, 0x66, 0x67, 0x68, 0x69, 0x6A, 0x73, 0x74, 0x75, 0x76, 0x77, 0x78, 0x79, 0x7A, 0x83, 0x84, 0x85,
    0x86, 0x87, 0x88, 0x89, 0x8A, 0x92, 0x93, 0x94, 0x95, 0x96, 0x97, 0x98, 0x99, 0x9A, 0xA2, 0xA3, 0xA4,
    0xA5, 0xA6, 0xA7, 0xA8, 0xA9, 0xAA, 0xB2, 0xB3, 0xB4, 0xB5, 0xB6, 0xB7, 0xB8, 0xB9, 0xBA, 0xC2, 0xC3,
    0xC4, 0xC5, 0xC6, 0xC7, 0xC8, 0xC9, 0xCA, 0xD2, 0xD3, 0xD4, 0xD5, 0xD6, 0xD7, 0xD8, 0xD9, 0xDA, 0xE1,
    0xE2, 0xE3, 0xE4, 0xE5, 0xE6, 0xE7, 0xE8, 0xE9, 0xEA, 0xF1, 0xF2, 0xF3, 0xF4, 0xF5, 0xF6, 0xF7, 0xF8,
    0xF9, 0xFA, 0xFF, 0xDA, 0x00, 0x0E, 0x04, 0x43, 0x00, 0x4D, 0x00, 0x59, 0x00, 0x4B, 0x00, 0x00, 0x3F,
    0x00, 0xEE, 0xEB, 0x9A, 0xAE, 0xC6, 0xBB, 0xDA, 0x28, 0xA2, 0x8A, 0xFF, 0xD9};

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
      {"CMYK JPEG", kCmykJpeg},
      {"empty", {}},
      {"text", {'h', 'e', 'l', 'l', 'o'}},
  };
  for (const auto& [name, bytes] : cases) {
    SCOPED_TRACE(name);
    cv::Mat image, reduced;
    EXPECT_EQ(stderr_of([&] { image = decode_image(bytes), reduced = decode_jpeg(bytes, DecodedColour::grey, 8); }), "");
    EXPECT_TRUE(image.empty());
    EXPECT_TRUE(reduced.empty());  // the stated size counts, not the reduced one
  }
  EXPECT_FALSE(cv::imdecode(kCmykJpeg, cv::IMREAD_COLOR).empty());  // a valid JPEG, refused for its colour space
}

// A sensor frame's pixel grid is the sensor's: an EXIF orientation tag (6: turn 90 degrees), which
// cv::imread and cv::imdecode apply, is ignored, as for every frame; formats other than JPEG and PNG
// go to OpenCV.
TEST(DecodeImage, ImageFilesKeepTheirPixelGridWhateverTheirExifTag) {
  const test::TempDir dir;
  const Bytes plain = encode(picture(), ".jpg");
  Bytes tagged(plain.begin(), plain.begin() + 2);
  const std::uint8_t exif[] = {0xFF, 0xE1, 0x00, 0x22, 'E', 'x', 'i', 'f', 0, 0, 'M', 'M', 0x00, 0x2A, 0, 0, 0, 8,  // TIFF header
                               0x00, 0x01, 0x01, 0x12, 0x00, 0x03, 0, 0, 0, 1, 0x00, 0x06, 0, 0, 0, 0, 0, 0};     // Orientation = 6
  tagged.insert(tagged.end(), std::begin(exif), std::end(exif));
  tagged.insert(tagged.end(), plain.begin() + 2, plain.end());
  const std::string jpeg = dir.file("turned \"`it's`\".jpg"), bmp = dir.file("frame.bmp");
  std::ofstream(jpeg, std::ios::binary).write(reinterpret_cast<const char*>(tagged.data()), std::streamsize(tagged.size()));
  ASSERT_EQ(cv::imread(jpeg, cv::IMREAD_COLOR).size(), cv::Size(250, 333));  // OpenCV turns it
  EXPECT_TRUE(same(read_image_file(jpeg), decode_jpeg(plain)));
  ASSERT_TRUE(cv::imwrite(bmp, picture()));
  EXPECT_TRUE(same(read_image_file(bmp), picture()));
  EXPECT_TRUE(read_image_file(dir.file("missing.png")).empty());
}

}  // namespace
}  // namespace haptex::dataset
