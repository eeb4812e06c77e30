// `--device replay:FILE[,KEY=VALUE,...]`: where the file name ends, what the keys set, the mode each
// kind of file is offered in, and every bad spec refused with the file or key and the fix.
#include <gtest/gtest.h>
#include <linux/videodev2.h>
#include <sys/stat.h>

#include <fstream>

#include "capture/recording/press_recorder.hpp"
#include "capture/replay/replay_device.hpp"
#include "core/error.hpp"
#include "core/h5/file.hpp"
#include "tests/capture/fake_setup.hpp"
#include "tests/capture/press_videos.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::capture {
namespace {

class ReplayDevice : public ::testing::Test {
 protected:
  // A short lossless press video (FFV1, as haptex synth writes them) named `name`.
  std::string video(const std::string& name, int fourcc = cv::VideoWriter::fourcc('F', 'F', 'V', '1')) const {
    const std::string path = dir_.file(name);
    fixtures::write_press_video(path, fixtures::quick_presses(1), 40, 160, 120, fourcc);
    return path;
  }
  // Expects parse_replay_device to refuse `device` as bad input, with every part in the message.
  static void expect_refused(const std::string& device, const std::vector<std::string>& parts) {
    try {
      parse_replay_device(device);
      ADD_FAILURE() << device << " was accepted";
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), Error::Kind::bad_input) << e.what();
      for (const auto& part : parts) EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    }
  }
  haptex::test::TempDir dir_;
};

TEST_F(ReplayDevice, OnlyReplayPrefixesAreReplays) {
  EXPECT_TRUE(is_replay_device("replay:x.avi"));
  EXPECT_FALSE(is_replay_device("fake:size=64x48"));
  EXPECT_FALSE(is_replay_device("/dev/video0"));
  EXPECT_FALSE(is_replay_device("replay"));
}

TEST_F(ReplayDevice, TheFileRunsToTheFirstCommaThatStartsAKey) {
  // Commas, spaces, quotes, back-quotes and shell syntax are part of the name; nothing runs them.
  const std::string path = video("take 1, \"it's\" `echo x` $(touch y),2.mkv");
  const FakeDevice plain = parse_replay_device("replay:" + path);
  EXPECT_EQ(plain.node, "replay:" + path);
  EXPECT_EQ(plain.config.capture_path, plain.node);
  EXPECT_TRUE(plain.config.realtime) << "at the file's rate unless lockstep";
  ASSERT_EQ(plain.config.modes.size(), 1u);
  EXPECT_EQ(plain.config.modes[0].fps, std::vector<double>{30.0});

  const FakeDevice keyed =
      parse_replay_device("replay:" + path + ",lockstep,fps=12.5,drop=5,error=2.5,corrupt=1,disconnect=40,stall=10:300,seed=7");
  EXPECT_EQ(keyed.node, "replay:" + path);
  const FakeCameraConfig& c = keyed.config;
  EXPECT_FALSE(c.realtime);
  EXPECT_EQ(c.modes[0].fps, std::vector<double>{12.5});
  EXPECT_DOUBLE_EQ(c.drop_percent, 5);
  EXPECT_DOUBLE_EQ(c.error_percent, 2.5);
  EXPECT_DOUBLE_EQ(c.corrupt_percent, 1);
  ASSERT_TRUE(c.disconnect_after.has_value());
  EXPECT_EQ(*c.disconnect_after, 40u);
  ASSERT_EQ(c.stalls.size(), 1u);
  EXPECT_EQ(c.stalls[0].before_frame, 10u);
  EXPECT_EQ(c.stalls[0].duration_ms, 300);
  EXPECT_EQ(c.seed, 7u);
  EXPECT_DOUBLE_EQ(parse_replay_device("replay:" + path + ",speed=4").config.speed, 4.0);
}

TEST_F(ReplayDevice, EachKindOfFileIsOfferedAsTheSensorSentIt) {
  // Lossless video: raw YUYV, so the recorder keeps it lossless.
  const FakeMode lossless = parse_replay_device("replay:" + video("ffv1.mkv")).config.modes.at(0);
  EXPECT_EQ(lossless.fourcc, std::uint32_t(V4L2_PIX_FMT_YUYV));
  EXPECT_EQ(lossless.width, 160u);
  EXPECT_EQ(lossless.height, 120u);
  EXPECT_EQ(lossless.max_payload, 0u) << "YUYV: exactly a frame";
  // Lossy video: MJPG, as GelSight-type sensors send, with room for any JPEG of the frame.
  const FakeMode lossy = parse_replay_device("replay:" + video("mjpg.avi", cv::VideoWriter::fourcc('M', 'J', 'P', 'G')))
                             .config.modes.at(0);
  EXPECT_EQ(lossy.fourcc, std::uint32_t(V4L2_PIX_FMT_MJPEG));
  EXPECT_GE(lossy.max_payload, 160u * 120u * 3);
  // A press file: its stored format, size and granted rate.
  FakeCamera camera(fixtures::small_camera(V4L2_PIX_FMT_MJPEG, 320, 240, 30));
  SessionRequest request;
  request.node = "/dev/video0";
  request.output_dir = dir_.file("session");
  RecorderOptions options;
  options.material = "Cork";
  options.presses = 1;
  ASSERT_EQ(record_session(camera, request, options).presses.size(), 1u);
  const std::string press_file = dir_.file("session/press_0.h5");
  const FakeMode press = parse_replay_device("replay:" + press_file).config.modes.at(0);
  EXPECT_EQ(press.fourcc, std::uint32_t(V4L2_PIX_FMT_MJPEG));
  EXPECT_EQ(press.width, 320u);
  EXPECT_EQ(press.fps, std::vector<double>{30.0});
  // A file that does not say its rate needs fps=.
  h5::File::open(press_file, true).root().set_attr("fps", 0.0);
  try {
    parse_replay_device("replay:" + press_file);
    ADD_FAILURE() << "a replay without a rate was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("does not say its frame rate"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("replay:" + press_file + ",fps=N"), std::string::npos) << e.what();
  }
  EXPECT_EQ(parse_replay_device("replay:" + press_file + ",fps=25").config.modes.at(0).fps, std::vector<double>{25.0});
}

TEST_F(ReplayDevice, RefusesMissingAndNonVideoFiles) {
  expect_refused("replay:", {"no file given", "replay:FILE"});
  expect_refused("replay:" + dir_.file("absent.avi"), {dir_.file("absent.avi"), "no such file", "replay:FILE"});
  expect_refused("replay:" + dir_.file("absent.avi") + ",lockstep", {dir_.file("absent.avi") + ": no such file"});
  expect_refused("replay:" + dir_.path().string(), {"is a folder", "one video or press file"});
  ASSERT_EQ(::mkfifo(dir_.file("pipe.avi").c_str(), 0600), 0);
  expect_refused("replay:" + dir_.file("pipe.avi"), {dir_.file("pipe.avi"), "not a regular file"});
  expect_refused("replay:/dev/null", {"/dev/null", "not a regular file"});
  std::ofstream(dir_.file("notes.avi")) << "not a video\n";
  expect_refused("replay:" + dir_.file("notes.avi"), {dir_.file("notes.avi"), "video"});
  std::ofstream(dir_.file("fake.h5")) << "not HDF5\n";
  expect_refused("replay:" + dir_.file("fake.h5"), {dir_.file("fake.h5"), "not an HDF5 file"});
  expect_refused("replay:caf\xe9.avi", {"not valid UTF-8", "byte 3"});
}

TEST_F(ReplayDevice, RefusesUnknownKeysAndBadValuesNamingThem) {
  const std::string path = video("v.mkv");
  const std::string usage = "replay:FILE[,fps=N,lockstep";
  // A misspelt key is no key, so it reads as part of the file name: the key is named all the same.
  expect_refused("replay:" + path + ",fsp=30", {"fsp", "unknown key", "after the file " + path, usage});
  expect_refused("replay:" + path + ",lockstep,fsp=30", {"fsp: unknown key", usage});
  // The fake camera's own keys: a replay's size, format and presses are the file's.
  expect_refused("replay:" + path + ",lockstep,size=64x48", {"size: unknown key"});
  expect_refused("replay:" + path + ",fps=0", {"fps", "1 to 1000"});
  expect_refused("replay:" + path + ",fps=fast", {"fps", "'fast' is not a number"});
  expect_refused("replay:" + path + ",drop=-5", {"drop", "'-5' is not a number from 0 to 1e12"});
  expect_refused("replay:" + path + ",disconnect=", {"disconnect", "'' is not a whole number"});
  expect_refused("replay:" + path + ",disconnect=inf", {"disconnect", "'inf' is not a whole number from 0 to 1e12"});
  expect_refused("replay:" + path + ",drop=1e-40", {"drop", "0 or at least 1.2e-38"});
  expect_refused("replay:" + path + ",drop=nan", {"drop", "'nan' is not a number"});
  expect_refused("replay:" + path + ",speed=1e999", {"speed", "'1e999' is not a number"});
  expect_refused("replay:" + path + ",stall=10", {"stall", "FRAME:MILLISECONDS"});
  expect_refused("replay:" + path + ",speed=0", {"speed", "from 0.01 to 100"});
  expect_refused("replay:" + path + ",speed=1e-40", {"speed", "0 or at least 1.2e-38"});
  expect_refused("replay:" + path + ",speed=1e-30", {"speed", "from 0.01 to 100"});
}

}  // namespace
}  // namespace haptex::capture
