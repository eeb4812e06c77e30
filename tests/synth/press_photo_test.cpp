#include "synth/photo_press.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <set>

#include "core/error.hpp"
#include "tests/support/npy.hpp"
#include "tests/support/sample_recording.hpp"
#include "tests/support/temp_dir.hpp"
#include "tests/synth/press_frames.hpp"

namespace haptex::synth {
namespace {

// A stand-in for a HaTT texture photograph: 1024 x 1024 colour texture with structure at every place,
// so crops from different places do not look alike.
std::string write_texture_photo(const test::TempDir& dir, const std::string& name = "Test Weave_square.jpg") {
  cv::Mat noise(1024, 1024, CV_8UC3);
  cv::RNG rng(1234);
  rng.fill(noise, cv::RNG::UNIFORM, 0, 256);
  cv::Mat photo;
  cv::GaussianBlur(noise, photo, cv::Size(0, 0), 3);
  cv::normalize(photo, photo, 20, 235, cv::NORM_MINMAX);
  const std::string path = dir.file(name);
  cv::imwrite(path, photo, {cv::IMWRITE_JPEG_QUALITY, 95});
  return path;
}

double correlation(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat ga, gb;
  cv::cvtColor(a, ga, cv::COLOR_BGR2GRAY);
  cv::cvtColor(b, gb, cv::COLOR_BGR2GRAY);
  cv::Mat result;
  cv::matchTemplate(ga, gb, result, cv::TM_CCOEFF_NORMED);  // same size: one normalised correlation
  return result.at<float>(0, 0);
}

TEST(PhotoPress, FiveCropsAtSeparatePlacesBecomePressVideos) {
  test::TempDir dir;
  const std::string photo_path = write_texture_photo(dir);
  const cv::Mat photo = cv::imread(photo_path);
  const std::string out = (dir.path() / "Test Weave").string();  // press folders are made inside an existing one
  const auto sidecars = write_photo_presses(photo_path, out, "Test Weave", 9);
  ASSERT_EQ(sidecars.size(), 5u);
  std::set<std::pair<int, int>> corners;
  for (const PressSidecar& written : sidecars) {
    SCOPED_TRACE("press " + std::to_string(written.press));
    const PressSidecar s = read_press_sidecar(press_sidecar_path(out, written.press));
    ASSERT_TRUE(s.crop_px.has_value());
    EXPECT_FALSE(s.location_mm.has_value());
    const auto [x, y, w, h] = *s.crop_px;
    EXPECT_EQ(w, 640);
    EXPECT_EQ(h, 480);
    corners.insert({x, y});

    const auto frames = test::read_press_frames(press_video_path(out, s.press));
    ASSERT_EQ(int(frames.size()), s.frames);
    EXPECT_EQ(frames[0].size(), cv::Size(640, 480));
    EXPECT_EQ(s.width, 640);
    EXPECT_EQ(s.height, 480);
    EXPECT_GE(s.contact_first, 15);
    // The peak frame is the crop (JPEG-decoded photograph plus noise); the quiet frames are flat gel.
    const cv::Mat crop = photo(cv::Rect(x, y, w, h));
    EXPECT_GT(correlation(frames[std::size_t(s.peak_frame)], crop), 0.95);
    EXPECT_LT(std::abs(correlation(frames[0], crop)), 0.1);
    EXPECT_LT(test::mean_abs_difference(frames[1], frames[0]), 1.5);
    EXPECT_EQ(test::frame_most_unlike_first(frames), s.peak_frame);
  }
  EXPECT_EQ(corners.size(), 5u);
  // Separate places: every two crops' corners at least 96 pixels apart along some axis.
  for (auto a = corners.begin(); a != corners.end(); ++a)
    for (auto b = std::next(a); b != corners.end(); ++b)
      EXPECT_GE(std::max(std::abs(a->first - b->first), std::abs(a->second - b->second)), 96);
}

TEST(PhotoPress, DeterministicForASeed) {
  test::TempDir dir;
  const std::string photo_path = write_texture_photo(dir);
  PhotoPressOptions small;
  small.presses = 2;
  small.width = 160;
  small.height = 120;
  write_photo_presses(photo_path, dir.file("a"), "Test Weave", 4, "haptex synth hatt", small);
  write_photo_presses(photo_path, dir.file("b"), "Test Weave", 4, "haptex synth hatt", small);
  const auto a = test::tree_contents(dir.file("a"));
  ASSERT_EQ(a.size(), 4u);  // two press videos and their sidecars
  EXPECT_TRUE(a == test::tree_contents(dir.file("b")));
}

TEST(PhotoPress, CropsStayDistinctOnASmallPhotograph) {
  PhotoPressOptions options;
  const auto crops = photo_crops({700, 500}, 1, options);  // room for 61 x 21 corner positions only
  std::set<std::pair<int, int>> corners;
  for (const cv::Rect& c : crops) {
    EXPECT_LE(c.x + c.width, 700);
    EXPECT_LE(c.y + c.height, 500);
    corners.insert({c.x, c.y});
  }
  EXPECT_EQ(corners.size(), 5u);
  EXPECT_THROW(photo_crops({600, 600}, 1, options), Error);
}

TEST(PhotoPress, RefusesUnreadableOrSmallPhotographs) {
  test::TempDir dir;
  test::write_text_file(dir.file("not_an_image.jpg"), "hello");
  try {
    write_photo_presses(dir.file("not_an_image.jpg"), dir.file("out"), "X", 1);
    FAIL() << "an unreadable photograph was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::bad_input);
    EXPECT_NE(std::string(e.what()).find("not_an_image.jpg"), std::string::npos);
  }
  cv::imwrite(dir.file("small.png"), cv::Mat(400, 400, CV_8UC3, cv::Scalar(1, 2, 3)));
  EXPECT_THROW(write_photo_presses(dir.file("small.png"), dir.file("out"), "X", 1), Error);
  EXPECT_FALSE(std::filesystem::exists(dir.file("out")));
}

// The real HaTT photographs, when ../shared/data is present.
TEST(PhotoPress, RealHattPhotograph) {
  const std::string shared = test::shared_data_dir();
  const std::string photo_path = shared + "/hatt/images/Book_square.jpg";
  if (shared.empty() || !std::filesystem::exists(photo_path)) GTEST_SKIP() << "no HaTT images in ../shared/data";
  test::TempDir dir;
  PhotoPressOptions one;
  one.presses = 1;
  const PressSidecar s = write_photo_presses(photo_path, dir.path().string(), "Book", 1, "test", one)[0];
  const auto frames = test::read_press_frames(press_video_path(dir.path().string(), 0));
  ASSERT_EQ(int(frames.size()), s.frames);
  EXPECT_EQ(frames[0].size(), cv::Size(640, 480));
  EXPECT_EQ(test::frame_most_unlike_first(frames), s.peak_frame);
}

}  // namespace
}  // namespace haptex::synth
