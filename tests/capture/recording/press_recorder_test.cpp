// The recorder against the fake camera in lockstep: presses become press files with every frame,
// faults end the take cleanly, and the manifest says what happened.
#include <gtest/gtest.h>
#include <linux/videodev2.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "capture/extraction/extract_presses.hpp"
#include "capture/recording/press_recorder.hpp"
#include "core/temporary_name.hpp"
#include "dataset/vlen_bytes.hpp"
#include "core/error.hpp"
#include "core/h5/file.hpp"
#include "core/json/schema.hpp"
#include "tests/capture/fake_setup.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::capture {
namespace {

namespace fs = std::filesystem;
using fixtures::small_camera;

RecorderOptions options(int presses = 3) {
  RecorderOptions o;
  o.material = "Brick 2";
  o.presses = presses;
  o.pre_frames = 5;
  o.post_frames = 5;
  o.stall_seconds = 0.5;
  return o;
}

class Recorder : public ::testing::Test {
 protected:
  RecordingResult record(FakeCameraConfig config, const RecorderOptions& o, const std::atomic<bool>* stop = nullptr,
                         const Progress& progress = {}, const UsbLink& link = {}, const Warn& warn = {}) {
    camera_ = std::make_unique<FakeCamera>(std::move(config));
    SessionRequest request;
    request.node = "/dev/video0";
    request.serial = "2BNK-CE6G";
    request.link = link;
    request.output_dir = dir_.file("session");
    request.command = "test";
    return record_session(*camera_, request, o, stop, progress, warn);
  }
  std::string file(const std::string& name) const { return dir_.file("session/" + name); }
  nlohmann::json manifest() const {
    const nlohmann::json doc = json::read_file(file("session.json"));
    json::validate(doc, "capture-session.schema.json", "session.json");
    return doc;
  }
  haptex::test::TempDir dir_;
  std::unique_ptr<FakeCamera> camera_;
};

TEST_F(Recorder, OnePressFilePerPressWithThePreTriggerFrames) {
  const RecordingResult r = record(small_camera(), options(3));
  EXPECT_EQ(r.ended_by, "presses");
  ASSERT_EQ(r.presses.size(), 3u);
  const FakeScene& scene = *camera_->scene();
  for (const auto& p : r.presses) {
    // The scene's sequence number is the take frame number (no frame lost in lockstep).
    // Contact is seen on the press's first or second frame (the first is barely pressed).
    EXPECT_GT(scene.depth(std::uint64_t(p.contact_first)), 0.0);
    EXPECT_EQ(scene.depth(std::uint64_t(p.contact_first - 2)), 0.0);
    EXPECT_EQ(p.take_first_frame, p.contact_first - 5) << "5 pre-trigger frames";
    EXPECT_EQ(p.take_last_frame, p.contact_last + 1 + 5) << "the release frame and 5 more";
    EXPECT_EQ(p.frames, std::uint64_t(p.take_last_frame - p.take_first_frame + 1));
    EXPECT_EQ(scene.depth(std::uint64_t(p.peak_frame)), 1.0);
    EXPECT_EQ(p.dropped_frames, 0u);
    EXPECT_EQ(p.ended_by, "release");
    EXPECT_TRUE(fs::exists(file(p.file)));
  }
  EXPECT_EQ(r.presses[1].contact_first - r.presses[0].contact_first, 28) << "the scene's press period";
  EXPECT_EQ(manifest()["presses"].size(), 3u);
  EXPECT_EQ(manifest()["ended_by"], "presses");
  EXPECT_EQ(manifest()["device"]["serial"], "2BNK-CE6G");
  EXPECT_EQ(manifest()["stream"]["fourcc"], "MJPG");
  EXPECT_EQ(manifest()["controls"]["missing"][0], "gain_automatic");
  EXPECT_FALSE(fs::exists(file("press_3.h5")));
}

TEST_F(Recorder, PressFilesHoldTheSensorsBytesUnchangedAndTheirMetadata) {
  const RecordingResult r = record(small_camera(), options(1));
  ASSERT_EQ(r.presses.size(), 1u);
  const RecordedPress& p = r.presses[0];
  h5::File f = h5::File::open(file("press_0.h5"));
  const h5::Group root = f.root();
  EXPECT_EQ(root.attr_string("haptex_format"), "press/1");
  EXPECT_EQ(root.attr_string("material"), "Brick 2");
  EXPECT_EQ(root.attr_string("fourcc"), "MJPG");
  EXPECT_EQ(root.attr_string("encoding"), "jpeg");
  EXPECT_EQ(root.attr_string("serial"), "2BNK-CE6G");
  EXPECT_EQ(root.attr_int("width"), 320);
  EXPECT_DOUBLE_EQ(root.attr_double("fps"), 30.0);
  EXPECT_EQ(root.attr_int("samples"), std::int64_t(p.frames));
  EXPECT_EQ(root.attr_int("contact_first"), 5);
  EXPECT_EQ(root.attr_int("dropped_frames"), 0);
  EXPECT_NE(root.attr_string("locked_controls").find("exposure_time_absolute"), std::string::npos);
  const auto sequence = root.open_dataset("sequence").read<std::uint32_t>();
  const auto stamps = root.open_dataset("timestamp_ns").read<std::int64_t>();
  ASSERT_EQ(sequence.size(), p.frames);
  ASSERT_EQ(stamps.size(), p.frames);
  const h5::Dataset frames = root.open_dataset("frames");
  for (std::size_t i = 0; i < p.frames; ++i) {
    EXPECT_EQ(sequence[i], std::uint32_t(p.take_first_frame) + i);
    EXPECT_EQ(dataset::read_vlen_bytes(frames, i), camera_->scene()->payload(sequence[i])) << "frame " << i << " re-encoded";
  }
  EXPECT_EQ(root.open_dataset("reference").shape(), (h5::Shape{240, 320, 3}));
  EXPECT_EQ(root.open_dataset("contrast").dtype(), "float32");
}

TEST_F(Recorder, YuyvFramesAreStoredAsLosslessPng) {
  const RecordingResult r = record(small_camera(V4L2_PIX_FMT_YUYV), options(1));
  ASSERT_EQ(r.presses.size(), 1u);
  h5::File f = h5::File::open(file("press_0.h5"));
  EXPECT_EQ(f.root().attr_string("encoding"), "png");
  const auto png = dataset::read_vlen_bytes(f.root().open_dataset("frames"), 3);
  const cv::Mat image = cv::imdecode(png, cv::IMREAD_COLOR);
  ASSERT_EQ(image.size(), cv::Size(320, 240));
  const std::uint32_t sequence = f.root().open_dataset("sequence").read<std::uint32_t>()[3];
  const std::vector<std::uint8_t>& yuyv = camera_->scene()->payload(sequence);
  cv::Mat expected;
  cv::cvtColor(cv::Mat(240, 320, CV_8UC2, const_cast<std::uint8_t*>(yuyv.data())), expected, cv::COLOR_YUV2BGR_YUYV);
  EXPECT_EQ(cv::norm(image, expected, cv::NORM_INF), 0.0);
  // And extraction reads them back: a lossless source, scored with the session's stored reference.
  ExtractOptions extract;
  extract.sheets = false;
  const ExtractResult x = extract_presses({file("press_0.h5")}, dir_.file("g.h5"), extract);
  ASSERT_EQ(x.presses.size(), 1u);
  // The fake presses equally deep for its hold frames, which then score alike up to noise; live
  // scores the Y plane, extraction the stored PNG's grey, so either may take a neighbouring hold frame.
  EXPECT_NEAR(double(x.presses[0].peak_index), double(r.presses[0].peak_frame - r.presses[0].take_first_frame), 1.0);
}

TEST_F(Recorder, ADisconnectDuringAPressKeepsEveryFrameTaken) {
  FakeCameraConfig config = small_camera();
  config.disconnect_after = 60 + 2;  // during the second press's contact (frames 58..)
  const RecordingResult r = record(config, options(5));
  EXPECT_EQ(r.ended_by, "disconnected");
  EXPECT_TRUE(r.device_fault());
  ASSERT_EQ(r.presses.size(), 2u);
  EXPECT_EQ(r.presses[0].ended_by, "release");
  EXPECT_EQ(r.presses[1].ended_by, "disconnected");
  EXPECT_EQ(r.presses[1].take_last_frame, 61) << "the last frame the sensor sent";
  h5::File f = h5::File::open(file("press_1.h5"));
  EXPECT_EQ(f.root().attr_string("ended_by"), "disconnected");
  EXPECT_EQ(f.root().open_dataset("frames").shape()[0], r.presses[1].frames);
  EXPECT_EQ(manifest()["ended_by"], "disconnected");
  EXPECT_EQ(manifest()["totals"]["frames"], 62);
}

TEST_F(Recorder, StopRequestClosesTheCurrentFileCleanly) {
  std::atomic<bool> stop{false};
  // Ctrl-C as soon as the second press makes contact.
  const Progress progress = [&](std::size_t, std::size_t, std::string_view what) {
    if (what == "press 1: contact") stop = true;
  };
  // In real time, as with a sensor: the processing thread keeps up, so the stop lands mid-press.
  FakeCameraConfig config = small_camera();
  config.realtime = true;
  config.speed = 2;
  const RecordingResult r = record(config, options(5), &stop, progress);
  EXPECT_EQ(r.ended_by, "interrupted");
  EXPECT_FALSE(r.device_fault());
  ASSERT_EQ(r.presses.size(), 2u);
  EXPECT_EQ(r.presses[1].ended_by, "interrupted");
  EXPECT_GT(r.presses[1].frames, 5u);
  EXPECT_NO_THROW(h5::File::open(file("press_1.h5")));
  EXPECT_TRUE(temporaries_of(file("press_1.h5")).empty());
  EXPECT_EQ(manifest()["ended_by"], "interrupted");
}

TEST_F(Recorder, LostErrorAndCorruptFramesAreCountedPerPressAndInTotal) {
  FakeCameraConfig config = small_camera();
  config.drop_percent = 5;
  config.error_percent = 5;
  config.corrupt_percent = 5;
  const RecordingResult r = record(config, options(3));
  ASSERT_EQ(r.presses.size(), 3u);
  const auto& fake = camera_->stats();
  EXPECT_EQ(r.totals.error_buffers, fake.error_buffers);
  EXPECT_GT(r.totals.dropped_frames, 0u);
  EXPECT_GT(r.totals.corrupt_frames, 0u) << "cut-off payloads are recognised";
  EXPECT_LE(r.totals.corrupt_frames, fake.corrupt_payloads);
  std::uint64_t press_drops = 0;
  for (const auto& p : r.presses) {
    press_drops += p.dropped_frames;
    // A corrupt frame is kept as sent, with no score.
    h5::File f = h5::File::open(file(p.file));
    const auto contrast = f.root().open_dataset("contrast").read<float>();
    EXPECT_EQ(std::uint64_t(std::count_if(contrast.begin(), contrast.end(), [](float c) { return std::isnan(c); })),
              p.corrupt_frames);
    EXPECT_EQ(f.root().attr_int("dropped_frames"), std::int64_t(p.dropped_frames));
    EXPECT_EQ(f.root().attr_int("error_frames"), std::int64_t(p.error_frames));
  }
  EXPECT_LE(press_drops, r.totals.dropped_frames);
  EXPECT_EQ(manifest()["totals"]["dropped_frames"], r.totals.dropped_frames);
  EXPECT_EQ(manifest()["totals"]["corrupt_frames"], r.totals.corrupt_frames);
  EXPECT_EQ(manifest()["totals"]["error_buffers"], r.totals.error_buffers);
}

TEST_F(Recorder, AStalledSensorEndsTheTake) {
  FakeCameraConfig config = small_camera();
  config.stalls = {{70, 5000}};  // five seconds without a frame, stall limit 0.5 s
  const RecordingResult r = record(config, options(5));
  EXPECT_EQ(r.ended_by, "stalled");
  EXPECT_GE(r.presses.size(), 1u);
  EXPECT_GT(r.totals.poll_timeouts, 0u);
}

TEST_F(Recorder, TheTimeLimitEndsTheTake) {
  FakeCameraConfig config = small_camera();
  config.realtime = true;
  config.speed = 10;
  RecorderOptions o = options(50);
  o.seconds = 0.5;
  const RecordingResult r = record(config, o);
  EXPECT_EQ(r.ended_by, "time limit");
  EXPECT_GE(r.presses.size(), 1u);
}

TEST_F(Recorder, RefusesAFolderThatHoldsASession) {
  record(small_camera(), options(1));
  try {
    record(small_camera(), options(1));
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::bad_input);
    EXPECT_NE(std::string(e.what()).find("already holds a capture session"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::exists(file("press_0.h5"))) << "the old session is untouched";
}

TEST_F(Recorder, RefusesBadOptionsBeforeTouchingTheDevice) {
  RecorderOptions o = options(1);
  o.reference_frames = 5;
  EXPECT_THROW(record(small_camera(), o), Error);
  EXPECT_EQ(camera_->open_descriptors(), 0u);
  o = options(0);
  EXPECT_THROW(record(small_camera(), o), Error);
}

// Section 3 of the any-sensor issue: a take that delivers fewer frames than granted says so.
TEST_F(Recorder, ATakeThatLosesFramesReportsTheRateItDelivered) {
  FakeCameraConfig config = small_camera();
  config.drop_percent = 30;
  const RecordingResult r = record(config, options(3));
  ASSERT_TRUE(r.totals.delivered_fps);
  const double kept = double(camera_->stats().delivered) / double(camera_->stats().produced);
  EXPECT_NEAR(*r.totals.delivered_fps, 30 * kept, 1.0) << "about 70 % of the 30 fps granted";
  EXPECT_LT(*r.totals.delivered_fps, 0.9 * 30);
  EXPECT_NE(r.delivery_warning.find("/dev/video0: the sensor delivered"), std::string::npos) << r.delivery_warning;
  EXPECT_NE(r.delivery_warning.find("below the 30 fps it granted"), std::string::npos) << r.delivery_warning;
  const nlohmann::json m = manifest();
  EXPECT_DOUBLE_EQ(m["totals"]["delivered_fps"].get<double>(), *r.totals.delivered_fps);
  ASSERT_EQ(m["warnings"].size(), 1u) << m["warnings"].dump();
  EXPECT_EQ(m["warnings"][0], r.delivery_warning);
}

TEST_F(Recorder, ACleanTakeMeasuresTheGrantedRateAndDoesNotWarn) {
  const RecordingResult r = record(small_camera(), options(2));
  ASSERT_TRUE(r.totals.delivered_fps);
  EXPECT_NEAR(*r.totals.delivered_fps, 30.0, 1e-3) << "the driver's timestamps are a period apart";
  EXPECT_EQ(r.delivery_warning, "");
  EXPECT_TRUE(manifest()["warnings"].empty()) << manifest()["warnings"].dump();
  EXPECT_FALSE(manifest()["device"].contains("usb_link")) << "the fake camera has no USB link";
}

TEST_F(Recorder, AModeTheLinkCannotCarryIsWarnedBeforeTheTake) {
  // Raw 320x240 at 30 fps is 36.9 Mbit/s; a USB 2.0 sensor behind a USB 1.1 hub gets 8.2 for video.
  std::vector<std::string> told;
  bool pressed_before_warning = false;
  const Progress progress = [&](std::size_t, std::size_t, std::string_view) { pressed_before_warning |= told.empty(); };
  const RecordingResult r = record(small_camera(V4L2_PIX_FMT_YUYV), options(1), nullptr, progress, UsbLink{12.0, 2.0},
                                   [&](const std::string& w) { told.push_back(w); });
  ASSERT_EQ(told.size(), 1u);
  EXPECT_FALSE(pressed_before_warning) << "the warning comes before the take";
  EXPECT_NE(told[0].find("YUYV 320x240 at 30 fps needs about 36.9 Mbit/s"), std::string::npos) << told[0];
  EXPECT_NE(told[0].find("USB 2.0 high speed port"), std::string::npos) << told[0];
  EXPECT_EQ(r.presses.size(), 1u) << "the take goes on: the user decides";
  const nlohmann::json m = manifest();
  EXPECT_EQ(m["warnings"][0], told[0]);
  EXPECT_EQ(m["device"]["usb_link"]["speed_mbps"], 12.0);
  EXPECT_NEAR(m["device"]["usb_link"]["stream_mbps_estimate"].get<double>(), 36.864, 1e-9);
  EXPECT_NEAR(m["device"]["usb_link"]["video_capacity_mbps"].get<double>(), 8.184, 1e-9);
  // The same sensor on its USB 2.0 link: nothing to say.
  told.clear();
  fs::remove_all(dir_.file("session"));
  record(small_camera(V4L2_PIX_FMT_YUYV), options(1), nullptr, {}, UsbLink{480.0, 2.0}, [&](const std::string& w) { told.push_back(w); });
  EXPECT_TRUE(told.empty());
  EXPECT_TRUE(manifest()["warnings"].empty());
}

TEST_F(Recorder, ATouchedSensorDuringTheReferenceIsWaitedFor) {
  FakeCameraConfig config = small_camera();
  config.scene.idle_frames = 8;  // warm-up 10 frames: the first press starts inside the reference frames
  const RecordingResult r = record(config, options(1));
  ASSERT_EQ(r.presses.size(), 1u);
  EXPECT_GT(r.presses[0].contact_first, 13 + 12) << "the first press fell into the reference and was skipped";
}

}  // namespace
}  // namespace haptex::capture
