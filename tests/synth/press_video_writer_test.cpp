#include "synth/press_video_writer.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/json/schema.hpp"
#include "tests/support/temp_dir.hpp"
#include "tests/synth/press_frames.hpp"

namespace haptex::synth {
namespace {
namespace fs = std::filesystem;

std::vector<cv::Mat> numbered_frames(int count, cv::Size size) {
  std::vector<cv::Mat> frames;
  for (int i = 0; i < count; ++i) {
    cv::Mat frame(size, CV_8UC3, cv::Scalar(10 + i, 100, 200 - i));
    frame.at<cv::Vec3b>(i % size.height, 3) = {255, 0, 255};
    frames.push_back(frame);
  }
  return frames;
}

PressSidecar sidecar_for(int press) {
  PressSidecar s;
  s.material = "Test Cloth";
  s.press = press;
  s.peak_frame = 20;
  s.contact_first = 16;
  s.contact_last = 25;
  s.peak_depth_mm = 0.123456789;
  s.location_mm = std::array<double, 2>{1.23456, 7.5};
  s.source = "haptex synth materials -n 1";
  return s;
}

TEST(PressVideoWriter, VideoReadsBackThroughOpenCV) {
  test::TempDir dir;
  const auto frames = numbered_frames(30, {64, 48});
  const PressSidecar written = write_press_video(dir.path().string(), frames, sidecar_for(2));
  EXPECT_EQ(written.frames, 30);
  EXPECT_EQ(written.width, 64);
  EXPECT_EQ(written.height, 48);

  cv::VideoCapture capture(press_video_path(dir.path().string(), 2));
  ASSERT_TRUE(capture.isOpened());
  EXPECT_EQ(capture.get(cv::CAP_PROP_FRAME_COUNT), 30);
  EXPECT_EQ(capture.get(cv::CAP_PROP_FOURCC), cv::VideoWriter::fourcc('M', 'J', 'P', 'G'));
  const auto decoded = test::read_press_frames(press_video_path(dir.path().string(), 2));
  ASSERT_EQ(decoded.size(), 30u);
  // JPEG at quality 95: each frame's flat colour within a grey level or two, in order.
  for (std::size_t i = 0; i < decoded.size(); ++i) EXPECT_LT(test::mean_abs_difference(decoded[i], frames[i]), 2.0) << i;
  // Only the finished press is left: no partial file.
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir.path())) names.insert(entry.path().filename().string());
  EXPECT_EQ(names, (std::set<std::string>{"press_2.avi", "press_2.json"}));
}

TEST(PressVideoWriter, SidecarFollowsItsSchemaAndReadsBack) {
  test::TempDir dir;
  write_press_video(dir.path().string(), numbered_frames(30, {64, 48}), sidecar_for(0));
  const std::string path = press_sidecar_path(dir.path().string(), 0);
  const nlohmann::json doc = json::read_file(path);
  EXPECT_NO_THROW(json::validate(doc, "press-sidecar.schema.json", path));
  EXPECT_EQ(doc["material"], "Test Cloth");
  EXPECT_EQ(doc["frames"], 30);
  EXPECT_EQ(doc["peak_frame"], 20);
  EXPECT_DOUBLE_EQ(doc["peak_depth_mm"].get<double>(), 0.123457);  // rounded to the micrometre
  EXPECT_FALSE(doc.contains("crop_px"));

  const PressSidecar back = read_press_sidecar(path);
  EXPECT_EQ(back.material, "Test Cloth");
  EXPECT_EQ(back.contact_first, 16);
  EXPECT_EQ(back.contact_last, 25);
  ASSERT_TRUE(back.location_mm.has_value());
  EXPECT_DOUBLE_EQ((*back.location_mm)[0], 1.2346);
  EXPECT_EQ(back.source, "haptex synth materials -n 1");
}

TEST(PressVideoWriter, BadSidecarLeavesNothingBehind) {
  test::TempDir dir;
  PressSidecar bad = sidecar_for(1);
  bad.peak_frame = 30;  // past the last frame
  EXPECT_THROW(write_press_video(dir.path().string(), numbered_frames(30, {64, 48}), bad), Error);
  bad = sidecar_for(1);
  bad.location_mm.reset();  // neither a location nor a crop
  EXPECT_THROW(write_press_video(dir.path().string(), numbered_frames(30, {64, 48}), bad), Error);
  EXPECT_TRUE(fs::is_empty(dir.path()));
}

TEST(PressVideoWriter, AbandonedPressLeavesNothingBehind) {
  test::TempDir dir;
  {
    PressVideoWriter writer(dir.path().string(), 0, 30);
    writer.add(numbered_frames(1, {64, 48})[0]);
    EXPECT_THROW(writer.add(cv::Mat(10, 10, CV_8UC3)), Error);  // a frame of another size
    EXPECT_THROW(writer.add(cv::Mat(48, 64, CV_8UC1)), Error);
  }
  EXPECT_TRUE(fs::is_empty(dir.path()));
}

// CI, stop 45: a signal took synth's temporary folder away while a press writer was starting, and the
// writer made the whole path again (left behind). A press folder is made only inside one that exists.
TEST(PressVideoWriter, APressFolderIsMadeOnlyInsideAnExistingFolder) {
  test::TempDir dir;
  const std::string gone = dir.file("out.ABCDEFGH.partial");
  EXPECT_THROW(PressVideoWriter(gone + "/gelsight/material", 0, 30), Error);
  EXPECT_TRUE(fs::is_empty(dir.path()));
  PressVideoWriter writer(dir.file("material"), 0, 30);  // one level is made
  EXPECT_TRUE(fs::is_directory(dir.file("material")));
}

TEST(PressVideoWriter, ReplacesAnOlderPress) {
  test::TempDir dir;
  write_press_video(dir.path().string(), numbered_frames(40, {64, 48}), sidecar_for(0));
  write_press_video(dir.path().string(), numbered_frames(30, {32, 24}), sidecar_for(0));
  const auto decoded = test::read_press_frames(press_video_path(dir.path().string(), 0));
  ASSERT_EQ(decoded.size(), 30u);
  EXPECT_EQ(decoded[0].size(), cv::Size(32, 24));
  EXPECT_EQ(read_press_sidecar(press_sidecar_path(dir.path().string(), 0)).frames, 30);
}

TEST(PressVideoWriter, SecondWriterOfTheSamePressIsRefused) {
  test::TempDir dir;
  PressVideoWriter first(dir.path().string(), 3, 30);
  try {
    PressVideoWriter second(dir.path().string(), 3, 30);
    FAIL() << "a second writer of press 3 was allowed";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::bad_input);
  }
}

TEST(PressVideoWriter, ReadingRefusesInconsistentSidecars) {
  test::TempDir dir;
  const std::string path = dir.file("press_0.json");
  nlohmann::json doc = {{"material", "X"},        {"press", 0},          {"fps", 30},          {"frames", 30},
                        {"width", 64},            {"height", 48},        {"peak_frame", 12},   {"contact_first", 15},
                        {"contact_last", 20},     {"peak_depth_mm", 0.1}, {"location_mm", {0, 0}}, {"source", "test"}};
  std::ofstream(path) << doc.dump();
  EXPECT_THROW(read_press_sidecar(path), Error);  // the peak lies before the contact
  doc["peak_frame"] = 17;
  doc["colour"] = "red";
  std::ofstream(path) << doc.dump();
  EXPECT_THROW(read_press_sidecar(path), Error);  // an unknown field
  doc.erase("colour");
  std::ofstream(path) << doc.dump();
  EXPECT_EQ(read_press_sidecar(path).peak_frame, 17);
}

}  // namespace
}  // namespace haptex::synth
