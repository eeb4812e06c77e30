// haptex trajectory (docs/render.md, "A trajectory to start from"): a recorded stroke's low-passed
// force and speed as the CSV render and play read, so docs/render.md's example runs as written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "dataset/format.hpp"
#include "dataset/object_paths.hpp"
#include "dataset/recordings_file.hpp"
#include "tests/support/mutations.hpp"
#include "tests/support/quick_models.hpp"
#include "tests/support/run_haptex.hpp"
#include "tests/support/small_pipeline.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {
namespace fs = std::filesystem;

TEST(TrajectoryCli, ARecordedStrokeIsWhatRenderPlays) {
  const TempDir dir;
  const SmallPipeline& p = small_pipeline();
  const CommandResult t = run_haptex({"--json", "trajectory", p.dataset, "--material", small_material(), "--start", "0.5", "--seconds", "1.2",
                                      "-o", dir.file("stroke.csv")});
  ASSERT_EQ(t.exit_code, 0) << t.err;
  EXPECT_EQ(nlohmann::json::parse(t.out)["samples"], 12000);
  // The rows are the recording's low-passed force and speed from 0.5 s on (negative ringing made 0).
  const dataset::RecordingSignals signals = dataset::read_recording_signals(
      dataset::open_checked(p.dataset, dataset::Kind::dataset).root().open_group(dataset::recording_path(small_material(), 0).substr(1)));
  std::ifstream csv(dir.file("stroke.csv"));
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "time_s,force_n,speed_mm_s");
  for (std::size_t i = 0; i < 12000 && std::getline(csv, line); i += 1) {
    const std::size_t a = line.find(','), b = line.find(',', a + 1);
    ASSERT_NEAR(std::stod(line.substr(a + 1, b - a - 1)), std::max(0.0f, signals.force_lp[5000 + i]), 1e-5) << "row " << i;
    ASSERT_NEAR(std::stod(line.substr(b + 1)), std::max(0.0f, signals.speed_lp[5000 + i]), 1e-3) << "row " << i;
  }
  const CommandResult r = run_haptex({"--json", "render", quick_model(), "--material", small_material(), "--trajectory", dir.file("stroke.csv"),
                                      "-o", dir.file("v.wav")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["samples"], 12000) << r.out;
}

// A file qa calls malformed is refused before trajectory reads it: with recordings numbered 0 and 2,
// "Give --recording 0 to 1" would name a recording that is not there.
TEST(TrajectoryCli, AFileWhoseRecordingsAreNotNumberedOnIsRefused) {
  const TempDir dir;
  const std::string recordings = copy_into(dir, small_pipeline().recordings, "gap.h5");
  const std::string group = "materials/" + small_material() + "/recordings";
  {
    Edit e(recordings);
    const std::size_t last = e.group(group).children().size() - 1;
    e.copy(group + "/" + std::to_string(last), group + "/" + std::to_string(last + 1));
    e.remove(group + "/" + std::to_string(last));
  }
  const CommandResult r = run_haptex({"trajectory", recordings, "--material", small_material(), "-o", dir.file("t.csv")});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("qa check layout."), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(recordings), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.file("t.csv")));
}

TEST(TrajectoryCli, ABadChoiceIsRefusedNamingWhatThereIs) {
  const TempDir dir;
  const SmallPipeline& p = small_pipeline();
  const auto run = [&](const std::vector<std::string>& more) {
    std::vector<std::string> args = {"trajectory", p.dataset, "-o", dir.file("t.csv")};
    args.insert(args.end(), more.begin(), more.end());
    return run_haptex(args);
  };
  const CommandResult material = run({"--material", "no_such"});
  EXPECT_EQ(material.exit_code, 2);
  EXPECT_NE(material.err.find("no such material. Use one of its ids: "), std::string::npos) << material.err;
  EXPECT_NE(material.err.find(small_material()), std::string::npos) << material.err;
  const CommandResult recording = run({"--material", small_material(), "--recording", "99"});
  EXPECT_EQ(recording.exit_code, 2);
  EXPECT_NE(recording.err.find("no such recording. Give --recording 0 to "), std::string::npos) << recording.err;
  const CommandResult late = run({"--material", small_material(), "--start", "1000"});
  EXPECT_EQ(late.exit_code, 2);
  EXPECT_NE(late.err.find("after its last sample (at 2.9999 s)"), std::string::npos) << late.err;
  // Review 19, F1: a start of 2^64 samples or more wrapped to sample 0 (exit 0, "from 1e+16 s"); a length as
  // long is the rest of the recording.
  for (const std::string start : {"1e16", "3.4e38"}) {
    const CommandResult far = run({"--material", small_material(), "--start", start, "--seconds", "0.5"});
    EXPECT_EQ(far.exit_code, 2) << start << far.err;
    EXPECT_NE(far.err.find("after its last sample"), std::string::npos) << far.err;
  }
  const CommandResult whole = run_haptex({"--json", "trajectory", p.dataset, "--material", small_material(), "--start", "2", "--seconds", "1e30",
                                          "-o", dir.file("rest.csv")});
  ASSERT_EQ(whole.exit_code, 0) << whole.err;
  EXPECT_EQ(nlohmann::json::parse(whole.out).at("samples"), 10000) << whole.out;  // 2 s to the end of a 3 s recording
  fs::remove(dir.file("rest.csv"));
  // Review 13: a stretch of no sample was written (exit 0); a path was taken for a material id; a start
  // inside the last sample's 0.1 ms was called past the end.
  const CommandResult empty = run({"--material", small_material(), "--seconds", "1e-9"});
  EXPECT_EQ(empty.exit_code, 2);
  EXPECT_NE(empty.err.find("fewer than the 10 (1.0 ms) a trajectory needs"), std::string::npos) << empty.err;
  for (const std::string& path :
       std::vector<std::string>{"/materials/" + small_material(), small_material() + "/", "/", small_material() + "/recordings"}) {
    const CommandResult r = run({"--material", path});
    EXPECT_EQ(r.exit_code, 2) << path;
    EXPECT_NE(r.err.find("no such material"), std::string::npos) << r.err;
  }
  EXPECT_FALSE(fs::exists(dir.file("t.csv")));
  const CommandResult last = run({"--material", small_material(), "--start", "2.99895"});  // the last 10 samples of the small pipeline's 3 s recordings
  EXPECT_EQ(last.exit_code, 0) << last.err;
  // --force replaces only a trajectory haptex wrote; never an input.
  std::ofstream(dir.file("mine.csv")) << "my notes\n";
  const CommandResult mine = run_haptex({"trajectory", p.dataset, "--material", small_material(), "-o", dir.file("mine.csv"), "--force"});
  EXPECT_EQ(mine.exit_code, 2) << mine.err;
  std::ifstream kept(dir.file("mine.csv"));
  std::string text;
  std::getline(kept, text);
  EXPECT_EQ(text, "my notes");
  const CommandResult input = run_haptex({"trajectory", p.dataset, "--material", small_material(), "-o", p.dataset, "--force"});
  EXPECT_EQ(input.exit_code, 2);
  EXPECT_NE(input.err.find("also an input"), std::string::npos) << input.err;
}

}  // namespace
}  // namespace haptex::test
