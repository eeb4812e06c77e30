// `haptex capture record --device replay:FILE` as a user runs it: the gsrobotics GelSight Mini video
// (../shared/data, skipped when absent) cuts the same presses live as `capture extract` finds in it
// offline; a press video made here ends the take "source ended", and its drops, error buffers and a
// disconnect are counted and handled as a sensor's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/json/schema.hpp"
#include "core/temporary_name.hpp"
#include "tests/capture/fake_setup.hpp"
#include "tests/capture/press_videos.hpp"
#include "tests/support/npy.hpp"
#include "tests/support/run_haptex.hpp"
#include "tests/support/temp_dir.hpp"
#include "tests/support/weak_footage.hpp"

namespace haptex::test {
namespace {

namespace fs = std::filesystem;

std::string mini_example() {
  const std::string root = shared_data_dir();
  const fs::path video = fs::path(root) / "gelsight" / "gsrobotics_gsmini_markers" / "mini_example.avi";
  return !root.empty() && fs::is_regular_file(video) ? video.string() : std::string();
}

class ReplayCli : public ::testing::Test {
 protected:
  // More presses than any file here holds, unless `extra` says otherwise: the file's end ends the take.
  CommandResult record(const std::string& device, const std::string& session, std::vector<std::string> extra = {}) const {
    std::vector<std::string> args = {"capture", "record", "--device", device, "--material", "Finger", "-o", dir_.file(session)};
    if (std::find(extra.begin(), extra.end(), "--presses") == extra.end()) extra.insert(extra.end(), {"--presses", "10"});
    args.insert(args.end(), extra.begin(), extra.end());
    return run_haptex(args);
  }
  nlohmann::json manifest(const std::string& session) const {
    const nlohmann::json m = nlohmann::json::parse(std::ifstream(dir_.file(session + "/session.json")));
    EXPECT_NO_THROW(json::validate(m, "capture-session.schema.json", "session.json"));
    return m;
  }
  // 3 presses of the fake scene (contact from frames 30, 58 and 86) in a 120-frame MJPG video at 30 fps.
  std::string press_video() const {
    const std::string path = dir_.file("presses.avi");
    capture::fixtures::write_press_video(path, capture::fixtures::quick_presses(3), 120, 320, 240,
                                         cv::VideoWriter::fourcc('M', 'J', 'P', 'G'));
    return path;
  }
  TempDir dir_;
};

// A replayed file starts with its first frame: no warm-up is dropped unless asked for (a sensor's
// black start-up frames are not in a file). A 48-frame video pressed from frame 12 records its press
// with the defaults; dropping 10 frames, as for a sensor, leaves a reference the press spoils.
TEST_F(ReplayCli, AReplayStartsWithTheFilesFirstFrame) {
  capture::PressSchedule s = capture::fixtures::quick_presses(1);
  s.black_frames = 0;
  s.idle_frames = 12;
  const std::string video = dir_.file("short.avi");
  capture::fixtures::write_press_video(video, s, 48, 320, 240, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'));
  const CommandResult r = record("replay:" + video + ",lockstep", "default");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json m = manifest("default");
  EXPECT_EQ(m["recorder"]["warmup_frames"], 0);
  ASSERT_EQ(m["presses"].size(), 1u) << r.out;
  EXPECT_GE(m["presses"][0]["peak_frame"].get<int>(), 12);
  const CommandResult sensor_like = record("replay:" + video + ",lockstep", "warm", {"--warmup", "10"});
  ASSERT_EQ(sensor_like.exit_code, 0) << sensor_like.err;
  EXPECT_EQ(manifest("warm")["recorder"]["warmup_frames"], 10);
  EXPECT_TRUE(manifest("warm")["presses"].empty());
}

// The tolerance: live, each frame is the video's frame re-encoded as JPEG (quality 95) and scored from
// a reduced-size JPEG decoding; offline, the decoded MPEG-4 frame is averaged over the same blocks.
// The two scoring images differ by a fraction of a grey level, which can move a threshold crossing
// by a frame where the score crosses slowly, or swap the peak between two near-equal frames. Measured
// on this video they agree exactly (57-86 peak 80, 90-152 peak 98, 160-207 peak 196).
TEST_F(ReplayCli, TheGsroboticsVideoCutsTheSamePressesLiveAsOffline) {
  const std::string video = mini_example();
  if (video.empty()) GTEST_SKIP() << "../shared/data/gelsight/gsrobotics_gsmini_markers/mini_example.avi is absent";
  const CommandResult live = record("replay:" + video + ",lockstep", "live");
  ASSERT_EQ(live.exit_code, 0) << live.err;
  EXPECT_NE(live.out.find("recorded 3 presses of Finger"), std::string::npos) << live.out;
  EXPECT_NE(live.out.find("(source ended): 219 frames, 0 dropped, 0 error buffers; MJPG 320x240 at 25 fps"),
            std::string::npos) << live.out;
  const nlohmann::json m = manifest("live");
  EXPECT_EQ(m["ended_by"], "source ended");
  EXPECT_EQ(m["device"]["node"], "replay:" + video);

  const CommandResult offline = run_haptex({"capture", "extract", video, "--material", "Finger", "-o", dir_.file("g.h5"),
                                            "--json", "--no-sheets"});
  ASSERT_EQ(offline.exit_code, 0) << offline.err;
  const nlohmann::json x = nlohmann::json::parse(offline.out);
  ASSERT_EQ(m["presses"].size(), x["presses"].size()) << "the same number of presses";
  ASSERT_EQ(m["presses"].size(), 3u);
  for (std::size_t j = 0; j < m["presses"].size(); ++j) {
    const nlohmann::json& l = m["presses"][j];
    const nlohmann::json& o = x["presses"][j];
    // No frame is lost in lockstep, so a take frame is the video's frame of the same number.
    EXPECT_LE(std::abs(l["contact_first"].get<int>() - o["contact_first"].get<int>()), 1) << "press " << j;
    EXPECT_LE(std::abs(l["contact_last"].get<int>() - o["contact_last"].get<int>()), 1) << "press " << j;
    EXPECT_LE(std::abs(l["peak_frame"].get<int>() - o["peak_index"].get<int>()), 2) << "press " << j;
    EXPECT_EQ(l["ended_by"], "release");
  }
}

// A weak press in a small MPEG-4 video (docs/capture.md, "Finding presses"): frames predicted from
// each other copy their compression noise, so live, as offline, the thresholds come from the 25
// frames after the reference, and the recorder cuts the press extraction finds.
TEST_F(ReplayCli, AWeakMpeg4PressIsCutLiveAsOffline) {
  const std::string video = dir_.file("weak.avi");
  const capture::fixtures::PressTiming timing;
  capture::fixtures::write_weak_video(video, capture::fixtures::press_sequence(capture::fixtures::synthetic_gel(),
                                                                               capture::fixtures::synthetic_gel_pressed(), timing),
                                      capture::fixtures::synthetic_gel(), {}, cv::VideoWriter::fourcc('m', 'p', '4', 'v'));
  const CommandResult live = record("replay:" + video + ",lockstep", "live", {"--warmup", "0"});
  ASSERT_EQ(live.exit_code, 0) << live.err;
  const nlohmann::json m = manifest("live");
  EXPECT_EQ(m["recorder"]["reference_restarts"], 0);
  const CommandResult offline = run_haptex({"capture", "extract", video, "--material", "Finger", "-o", dir_.file("g.h5"),
                                            "--json", "--no-sheets"});
  ASSERT_EQ(offline.exit_code, 0) << offline.err;
  const nlohmann::json x = nlohmann::json::parse(offline.out);
  ASSERT_EQ(m["presses"].size(), 1u) << live.out;
  ASSERT_EQ(x["presses"].size(), 1u) << offline.out;
  const nlohmann::json &l = m["presses"][0], &o = x["presses"][0];
  EXPECT_LE(std::abs(l["contact_first"].get<int>() - o["contact_first"].get<int>()), 1);
  // The 20 held frames are one picture under fresh noise: its peak is any of them, and live (frames
  // re-encoded as JPEG) and offline (MPEG-4 decoded) may pick different ones.
  const int hold_first = timing.first_contact() + timing.ramp, hold_last = hold_first + timing.hold - 1;
  for (const int peak : {l["peak_frame"].get<int>(), o["peak_index"].get<int>()}) {
    EXPECT_GE(peak, hold_first);
    EXPECT_LE(peak, hold_last);
  }
  // The same no-contact level, from the same frames scored alike (a JPEG re-encoding apart).
  const double live_level = m["recorder"]["no_contact_level"], offline_level = x["detection"][0]["no_contact_level"];
  EXPECT_NEAR(live_level, offline_level, 0.1 * offline_level);
  EXPECT_GT(offline_level, 0.0);
}

// Touched while its reference frames are taken (frames 4 to 7), an MPEG-4 take starts its reference
// again, and then calibrates on the frames after the new reference: only the later press is cut.
TEST_F(ReplayCli, AnMpeg4TakeTouchedDuringItsReferenceTakesItAgain) {
  using namespace capture::fixtures;
  const PressTiming touch{4, 1, 2, 70}, press;
  std::vector<cv::Mat> frames = press_sequence(synthetic_gel(), synthetic_gel_pressed(), touch);
  const std::vector<cv::Mat> later = press_sequence(synthetic_gel(), synthetic_gel_pressed(), press);
  frames.insert(frames.end(), later.begin(), later.end());
  const std::string video = dir_.file("touched.avi");
  write_weak_video(video, frames, synthetic_gel(), {}, cv::VideoWriter::fourcc('m', 'p', '4', 'v'));
  const CommandResult live = record("replay:" + video + ",lockstep", "live", {"--warmup", "0"});
  ASSERT_EQ(live.exit_code, 0) << live.err;
  const nlohmann::json m = manifest("live");
  EXPECT_GE(m["recorder"]["reference_restarts"].get<int>(), 1) << "the touched reference was refused";
  ASSERT_EQ(m["presses"].size(), 1u) << live.out;
  const int peak = m["presses"][0]["peak_frame"];
  EXPECT_GE(peak, touch.frames() + press.first_contact());
  EXPECT_LE(peak, touch.frames() + press.last_contact());
}

// At the file's rate: the take lasts as long as the video, and every frame is taken or counted lost.
TEST_F(ReplayCli, TheGsroboticsVideoPlaysAtItsFrameRate) {
  const std::string video = mini_example();
  if (video.empty()) GTEST_SKIP() << "../shared/data/gelsight/gsrobotics_gsmini_markers/mini_example.avi is absent";
  const CommandResult r = record("replay:" + video + ",speed=4", "timed");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json m = manifest("timed");
  EXPECT_EQ(m["ended_by"], "source ended");
  EXPECT_GE(m["totals"]["wall_seconds"].get<double>(), 0.95 * 219 / 25 / 4) << "219 frames at 4 x 25 fps";
  EXPECT_EQ(m["totals"]["frames"].get<int>() + m["totals"]["dropped_frames"].get<int>(), 219);
}

TEST_F(ReplayCli, AVideoEndsTheTakeCleanly) {
  const std::string video = press_video();
  const CommandResult r = record("replay:" + video + ",lockstep", "s");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(only_progress_lines(r.err)) << r.err;
  EXPECT_NE(r.out.find("recorded 3 presses of Finger into " + dir_.file("s") + " (source ended): 120 frames"), std::string::npos)
      << r.out;
  const nlohmann::json m = manifest("s");
  EXPECT_EQ(m["presses"].size(), 3u);
  EXPECT_EQ(m["device"]["driver"], "haptex replay");
  for (const auto& p : m["presses"]) EXPECT_TRUE(fs::exists(dir_.file("s/" + p["file"].get<std::string>())));
  // --presses still ends the take first when the file holds more presses.
  const CommandResult two = record("replay:" + video + ",lockstep", "two", {"--presses", "2"});
  ASSERT_EQ(two.exit_code, 0) << two.err;
  EXPECT_EQ(manifest("two")["ended_by"], "presses");
}

TEST_F(ReplayCli, DropsErrorBuffersAndADisconnectAreASensors) {
  const std::string video = press_video();
  const CommandResult faulty = record("replay:" + video + ",lockstep,drop=6,error=6,seed=3", "faulty");
  ASSERT_EQ(faulty.exit_code, 0) << faulty.err;
  const nlohmann::json t = manifest("faulty")["totals"];
  EXPECT_GT(t["dropped_frames"].get<int>(), 0);
  EXPECT_GT(t["error_buffers"].get<int>(), 0);
  EXPECT_EQ(t["frames"].get<int>() + t["dropped_frames"].get<int>() + t["error_buffers"].get<int>(), 120)
      << "every frame of the file is taken, lost or an error buffer";

  const CommandResult unplugged = record("replay:" + video + ",lockstep,disconnect=64", "unplugged");
  EXPECT_EQ(unplugged.exit_code, 1);
  EXPECT_NE(unplugged.err.find("replay:" + video + ": the sensor was disconnected after 64 frames; 2 presses saved"),
            std::string::npos) << unplugged.err;
  const nlohmann::json m = manifest("unplugged");
  EXPECT_EQ(m["ended_by"], "disconnected");
  ASSERT_EQ(m["presses"].size(), 2u);
  EXPECT_EQ(m["presses"][1]["ended_by"], "disconnected");
  EXPECT_EQ(m["presses"][1]["take_last_frame"], 63) << "the last frame taken is kept";
  EXPECT_TRUE(temporaries_of(dir_.file("unplugged/press_1.h5")).empty());
}

TEST_F(ReplayCli, APressFileRecordedFromAReplayReplaysAgain) {
  const CommandResult first = record("replay:" + press_video() + ",lockstep", "first", {"--pre-frames", "15"});
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const CommandResult again = record("replay:" + dir_.file("first/press_1.h5") + ",lockstep", "again", {"--warmup", "0"});
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.out.find("recorded 1 presses of Finger"), std::string::npos) << again.out;
  EXPECT_EQ(manifest("again")["ended_by"], "source ended");
}

TEST_F(ReplayCli, BadSpecsAreRefusedBeforeAnythingIsWritten) {
  const std::string video = press_video();
  struct Case {
    std::string device;
    std::vector<std::string> mentions;
  };
  const std::vector<Case> cases = {
      {"replay:" + dir_.file("absent.avi"), {dir_.file("absent.avi") + ": no such file", "replay:FILE"}},
      {"replay:" + video + ",fsp=25", {"fsp", "unknown key", "replay:FILE[,fps=N"}},
      {"replay:" + video + ",lockstep,size=64x48", {"size: unknown key"}},
      {"replay:" + video + ",fps=0", {"fps", "1 to 1000"}},
      {"replay:" + video + ",drop=many", {"drop", "'many' is not a number"}},
      {"replay:", {"no file given"}},
  };
  for (const Case& c : cases) {
    const CommandResult r = record(c.device, "refused");
    EXPECT_EQ(r.exit_code, 2) << c.device << ": " << r.err;
    for (const auto& part : c.mentions) EXPECT_NE(r.err.find(part), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one clear message: " << r.err;
    EXPECT_FALSE(fs::exists(dir_.file("refused"))) << c.device << ": nothing was created";
  }
}

}  // namespace
}  // namespace haptex::test
