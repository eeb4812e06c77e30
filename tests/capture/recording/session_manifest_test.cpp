#include <gtest/gtest.h>
#include <linux/videodev2.h>

#include <nlohmann/json.hpp>

#include "capture/recording/session_manifest.hpp"
#include "core/error.hpp"
#include "core/json/schema.hpp"
#include "core/temporary_name.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::capture {
namespace {

SessionDescription session() {
  SessionDescription s;
  s.command = "haptex capture record --serial 2BNK-CE6G --material Cork -o cork";
  s.material = "Cork";
  s.identity = {"/dev/video2", "GelSight Mini R0B 2BNK-CE6G: Ge", "uvcvideo", "usb-0000:00:14.0-2", 0};
  s.serial = "2BNK-CE6G";
  s.model = "GelSight Mini";
  s.format.fourcc = V4L2_PIX_FMT_MJPEG;
  s.format.width = 3280;
  s.format.height = 2464;
  s.format.interval_numerator = 1;
  s.format.interval_denominator = 25;
  s.format.requested_fps = 25;
  s.buffers = 6;
  s.controls.locked = {{"exposure_time_absolute", V4L2_CID_EXPOSURE_ABSOLUTE, 166, false}};
  s.controls.missing = {"gain_automatic"};
  s.warmup_frames = s.reference_frames = s.pre_frames = s.post_frames = 10;
  return s;
}

TEST(SessionManifest, FollowsItsSchemaAndIsWrittenAtomically) {
  RecordedPress p;
  p.file = "press_0.h5";
  p.frames = 40;
  p.ended_by = "release";
  p.sha256 = std::string(64, 'a');
  const ReferenceSummary reference{.noise = 0.4f, .pixel_threshold = 0.4f, .level = 0.1f, .trigger = 0.25f,
                                    .release = 0.175f, .restarts = 1};
  const nlohmann::json doc = session_manifest(session(), reference, {p}, {}, "presses");
  EXPECT_NO_THROW(json::validate(doc, "capture-session.schema.json", "session.json"));
  EXPECT_EQ(doc["recorder"]["no_contact_level"], 0.1f);
  EXPECT_EQ(doc["recorder"]["reference_restarts"], 1);
  EXPECT_EQ(doc["stream"]["granted_fps"], 25.0);
  EXPECT_EQ(doc["device"]["model"], "GelSight Mini");
  haptex::test::TempDir dir;
  write_session_manifest(dir.file("session.json"), doc);
  EXPECT_EQ(json::read_file(dir.file("session.json")), doc);
  EXPECT_TRUE(temporaries_of(dir.file("session.json")).empty());
}

TEST(SessionManifest, TheSchemaCatchesMistakes) {
  nlohmann::json doc = session_manifest(session(), {}, {}, {}, "presses");
  nlohmann::json bad = doc;
  bad["ended_by"] = "finished";
  EXPECT_THROW(json::validate(bad, "capture-session.schema.json", "session.json"), Error);
  bad = doc;
  bad["stream"]["buffers"] = 2;
  EXPECT_THROW(json::validate(bad, "capture-session.schema.json", "session.json"), Error);
  bad = doc;
  bad["material_id"] = "Cork";
  EXPECT_THROW(json::validate(bad, "capture-session.schema.json", "session.json"), Error);
  haptex::test::TempDir dir;
  EXPECT_THROW(write_session_manifest(dir.file("session.json"), bad), Error);
  EXPECT_FALSE(std::filesystem::exists(dir.file("session.json")));
}

}  // namespace
}  // namespace haptex::capture
