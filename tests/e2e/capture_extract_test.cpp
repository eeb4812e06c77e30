// `haptex capture extract` as a user runs it: press videos (as `haptex synth` writes them) and press
// files into the gelsight file, checked with h5py against schemas/hdf5-layout.md; bad input refused
// with exit code 2, and nothing left behind.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <regex>

#include "core/temporary_name.hpp"
#include "tests/capture/fake_setup.hpp"
#include "tests/capture/press_videos.hpp"
#include "tests/support/file_text.hpp"
#include "tests/support/run_haptex.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {

namespace fs = std::filesystem;

class ExtractCli : public ::testing::Test {
 protected:
  void SetUp() override {
    for (const char* material : {"Brick 2", "Cork"}) {
      fs::create_directories(dir_.path() / "gelsight" / material);
      for (int j = 0; j < 2; ++j)
        capture::fixtures::write_press_video(
            (dir_.path() / "gelsight" / material / ("press_" + std::to_string(j) + ".mkv")).string(),
            capture::fixtures::quick_presses(1), 45);
    }
  }
  std::string out() const { return dir_.file("gelsight.h5"); }
  void expect_nothing_written() const {
    EXPECT_FALSE(fs::exists(out()));
    EXPECT_TRUE(temporaries_of(out()).empty());
    EXPECT_FALSE(fs::exists(dir_.file("gelsight_sheets")));
    EXPECT_TRUE(temporaries_of(dir_.file("gelsight_sheets")).empty());
  }
  // check_layout.py on a copy of the layout whose H and W are this file's frame size, and whose
  // variable-length dtype has h5py's name (the script takes extents and dtypes literally).
  CommandResult check_layout(const std::string& file, const std::string& section, int height, int width) const {
    std::ifstream in(std::string(HAPTEX_SCHEMA_DIR) + "/hdf5-layout.md");
    std::string text((std::istreambuf_iterator<char>(in)), {});
    text = std::regex_replace(text, std::regex("\\(H, W, 3\\)"), "(" + std::to_string(height) + ", " + std::to_string(width) + ", 3)");
    text = std::regex_replace(text, std::regex("\\(12, H, W, 3\\)"), "(12, " + std::to_string(height) + ", " + std::to_string(width) + ", 3)");
    text = std::regex_replace(text, std::regex("\\| vlen \\|"), "| object |");
    std::ofstream(dir_.file("layout.md")) << text;
    const std::string script = std::string(HAPTEX_SCHEMA_DIR) + "/../tests/e2e/check_layout.py";
    return run_python({script, dir_.file("layout.md"), file, section});
  }
  TempDir dir_;
};

TEST_F(ExtractCli, AFolderOfMaterialsBecomesTheGelsightFile) {
  const CommandResult r = run_haptex({"capture", "extract", dir_.file("gelsight"), "-o", out()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("wrote " + out() + ": 4 presses of 2 materials from 4 files"), std::string::npos) << r.out;
  EXPECT_TRUE(only_progress_lines(r.err)) << r.err;
  EXPECT_TRUE(fs::exists(dir_.file("gelsight_sheets/brick_2_press_1.png")));
  const CommandResult info = run_haptex({"info", out()});
  ASSERT_EQ(info.exit_code, 0) << info.err;
  EXPECT_NE(info.out.find("gelsight/2"), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("brick_2 (Brick 2)"), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("presses: 2"), std::string::npos) << info.out;
}

TEST_F(ExtractCli, JsonListsEveryPress) {
  const CommandResult r = run_haptex({"capture", "extract", dir_.file("gelsight/Cork"), "-o", out(), "--json", "--no-sheets"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json doc = nlohmann::json::parse(r.out);
  ASSERT_EQ(doc["presses"].size(), 2u);
  EXPECT_EQ(doc["presses"][1]["material"], "Cork");
  EXPECT_EQ(doc["presses"][1]["press"], 1);
  EXPECT_EQ(doc["sheets"], "");
  EXPECT_FALSE(fs::exists(dir_.file("gelsight_sheets")));
}

// Review 5: --frames-per-press 5 wrote a file that qa (and so align and merge) refused, the layout
// saying 12 frames.
TEST_F(ExtractCli, AnyFramesPerPressGivesAFileOfTheLayout) {
  const CommandResult r = run_haptex({"capture", "extract", dir_.file("gelsight/Cork"), "-o", out(), "--no-sheets", "--frames-per-press", "5"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const CommandResult qa = run_haptex({"qa", out()});  // 2 presses: too few to split, so qa's verdict is "errors"
  EXPECT_TRUE(std::regex_search(qa.out, std::regex("layout.shape +error +pass"))) << qa.out;
  EXPECT_TRUE(std::regex_search(qa.out, std::regex("gelsight.frame_numbers +error +pass"))) << qa.out;
  if (!python_has("h5py")) GTEST_SKIP() << "python3-h5py is not installed (make deps installs it)";
  const CommandResult shape = run_python({"-c", "import h5py,sys; g=h5py.File(sys.argv[1])['materials/cork/presses/1']; "
                                          "print(g['frames'].shape, g['frame_indices'].shape)", out()});
  EXPECT_EQ(shape.out, "(5,) (5,)\n") << shape.err;
}

TEST_F(ExtractCli, H5pyReadsTheDocumentedLayout) {
  if (!python_has("h5py"))
    GTEST_SKIP() << "python3-h5py is not installed (make deps installs it)";
  ASSERT_EQ(run_haptex({"capture", "extract", dir_.file("gelsight"), "-o", out()}).exit_code, 0);
  const CommandResult gelsight = check_layout(out(), "GelSight file", 120, 160);
  EXPECT_EQ(gelsight.exit_code, 0) << gelsight.out << gelsight.err;
  EXPECT_NE(gelsight.out.find("layout ok"), std::string::npos) << gelsight.out << gelsight.err;

  const std::string session = dir_.file("session");
  ASSERT_EQ(run_haptex({"capture", "record", "--device", "fake:size=320x240,lockstep", "--material", "Cork",
                        "--presses", "1", "-o", session})
                .exit_code,
            0);
  const CommandResult press = check_layout(session + "/press_0.h5", "Press file", 240, 320);
  EXPECT_EQ(press.exit_code, 0) << press.out << press.err;
  // The checker must catch a file that breaks the layout.
  fs::copy_file(out(), dir_.file("broken.h5"));
  ASSERT_EQ(run_python({"-c", "import h5py, sys; f = h5py.File(sys.argv[1], 'a'); del f['materials/cork/presses/1/peak_index']",
                        dir_.file("broken.h5")})
                .exit_code,
            0);
  const CommandResult broken = check_layout(dir_.file("broken.h5"), "GelSight file", 120, 160);
  EXPECT_NE(broken.exit_code, 0);
  EXPECT_NE(broken.out.find("missing: /materials/cork/presses/1/peak_index"), std::string::npos) << broken.out;
}

// What `make demo` does: haptex synth writes press videos with their true peaks in sidecars.
TEST_F(ExtractCli, FindsThePeaksOfSynthPressVideos) {
  const std::string synth = dir_.file("synth");
  // One material: the first of the demo set is a polished one, whose presses are the faintest.
  const CommandResult made = run_haptex({"synth", "materials", "-n", "1", "--recordings", "1", "--presses", "2",
                                         "--seconds", "0.2", "--size", "320x240", "-o", synth});
  ASSERT_EQ(made.exit_code, 0) << made.err;
  const CommandResult r = run_haptex({"capture", "extract", synth + "/gelsight", "-o", out(), "--json", "--no-sheets"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json doc = nlohmann::json::parse(r.out);
  ASSERT_EQ(doc["presses"].size(), 2u) << r.out;
  for (const auto& p : doc["presses"]) {
    const fs::path press = fs::path(p["source"].get<std::string>());
    const nlohmann::json truth = nlohmann::json::parse(std::ifstream(fs::path(press).replace_extension(".json")));
    EXPECT_EQ(p["press_in_source"], 0);
    EXPECT_EQ(p["material"], truth["material"]);
    // Within 4 frames: the faint presses of a polished surface, as broad as the gel, share part of
    // their change with the drift fit's tilt, which moves the peak up to 4 frames earlier along its
    // plateau (docs/capture.md, "The contact score").
    EXPECT_NEAR(p["peak_index"].get<double>(), truth["peak_frame"].get<double>(), 4.0) << press;
    EXPECT_LE(p["contact_first"].get<int>(), truth["peak_frame"].get<int>());
    EXPECT_GE(p["contact_last"].get<int>(), truth["peak_frame"].get<int>());
  }
}

TEST_F(ExtractCli, NoPressAnywhereExitsOneAndWritesNothing) {
  fs::create_directories(dir_.path() / "still" / "Glass");
  auto schedule = capture::fixtures::quick_presses(0);
  capture::fixtures::write_press_video(dir_.file("still/Glass/still.mkv"), schedule, 30);
  const CommandResult r = run_haptex({"capture", "extract", dir_.file("still"), "-o", out()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("no press found"), std::string::npos) << r.err;
  expect_nothing_written();
  // --json still says what each source was judged by, then fails the same way.
  const CommandResult j = run_haptex({"--json", "capture", "extract", dir_.file("still"), "-o", out()});
  EXPECT_EQ(j.exit_code, 1);
  EXPECT_NE(j.err.find("no press found"), std::string::npos) << j.err;
  const auto result = nlohmann::json::parse(j.out);
  EXPECT_TRUE(result["output"].is_null());
  EXPECT_TRUE(result["sheets"].is_null());
  EXPECT_TRUE(result["presses"].empty());
  ASSERT_EQ(result["detection"].size(), 1u) << j.out;
  const auto& d = result["detection"][0];
  EXPECT_EQ(d["presses"], 0);
  EXPECT_LT(d["highest_score"].get<double>(), d["trigger"].get<double>());
  EXPECT_GT(d["no_contact_level"].get<double>(), 0.0);
  expect_nothing_written();
}

// --explain: one score chart per source, pressed or not, named after the source, and kept when no
// source holds a press (it says why); --json names the folder and where each reference came from.
TEST_F(ExtractCli, ExplainChartsEverySourceEvenWithoutAPress) {
  fs::create_directories(dir_.path() / "still" / "Glass");
  capture::fixtures::write_press_video(dir_.file("still/Glass/still.mkv"), capture::fixtures::quick_presses(0), 30);
  const CommandResult none = run_haptex({"capture", "extract", dir_.file("still"), "-o", out(), "--explain"});
  EXPECT_EQ(none.exit_code, 1);
  EXPECT_NE(none.err.find("Each source's score over time: " + dir_.file("gelsight_explain")), std::string::npos) << none.err;
  EXPECT_TRUE(fs::is_regular_file(dir_.file("gelsight_explain/still_mkv.png")));
  EXPECT_FALSE(fs::exists(out()));

  const CommandResult r = run_haptex({"--json", "capture", "extract", dir_.file("gelsight/Cork"), dir_.file("still"), "-o",
                                      out(), "--explain", "--force"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json doc = nlohmann::json::parse(r.out);
  EXPECT_EQ(doc["explain"], dir_.file("gelsight_explain"));
  ASSERT_EQ(doc["detection"].size(), 3u);
  for (const auto& d : doc["detection"]) EXPECT_EQ(d["reference_kind"], "start") << d.dump();
  // Charts are named after their source as an id; each detection names its own.
  for (const char* chart : {"press_0_mkv.png", "press_1_mkv.png", "still_mkv.png"})
    EXPECT_EQ(cv::imread(dir_.file(std::string("gelsight_explain/") + chart)).cols, 960) << chart;
  EXPECT_EQ(doc["detection"][2]["chart"], dir_.file("gelsight_explain/still_mkv.png"));
  // Two sources of one name in two folders get two charts.
  const CommandResult twice = run_haptex({"--json", "capture", "extract", dir_.file("gelsight/Cork/press_0.mkv"),
                                          dir_.file("gelsight/Brick 2/press_0.mkv"), "-o", out(), "--explain", "--force"});
  ASSERT_EQ(twice.exit_code, 0) << twice.err;
  const nlohmann::json t = nlohmann::json::parse(twice.out);
  EXPECT_EQ(t["detection"][0]["chart"], dir_.file("gelsight_explain/press_0_mkv.png"));
  EXPECT_EQ(t["detection"][1]["chart"], dir_.file("gelsight_explain/press_0_mkv_2.png"));
  EXPECT_TRUE(fs::is_regular_file(dir_.file("gelsight_explain/press_0_mkv_2.png")));
  // Review 22, F2: a run that finds no press keeps the file at -o, and so the charts that describe it.
  const std::string before = file_text(out());
  const CommandResult still = run_haptex({"capture", "extract", dir_.file("still"), "-o", out(), "--explain", "--force"});
  EXPECT_EQ(still.exit_code, 1);
  EXPECT_NE(still.err.find("The score charts were not written: " + dir_.file("gelsight_explain") + " belongs to " + out()), std::string::npos)
      << still.err;
  EXPECT_EQ(file_text(out()), before);
  EXPECT_TRUE(fs::is_regular_file(dir_.file("gelsight_explain/press_0_mkv_2.png")));
  EXPECT_FALSE(fs::exists(dir_.file("gelsight_explain/still_mkv.png")));
}

TEST_F(ExtractCli, BadInputIsRefusedWithOneMessageAndNothingWritten) {
  const auto refused = [&](std::vector<std::string> args, const std::vector<std::string>& parts) {
    args.insert(args.begin(), {"capture", "extract"});
    const CommandResult r = run_haptex(args);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    for (const auto& part : parts) EXPECT_NE(r.err.find(part), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one clear message: " << r.err;
    expect_nothing_written();
  };
  refused({dir_.file("nowhere"), "-o", out()}, {"nowhere: no such file or directory"});
  std::ofstream(dir_.file("gelsight/Cork/press_2.mkv")) << "truncated";
  refused({dir_.file("gelsight"), "-o", out()}, {"press_2.mkv", "OpenCV cannot open this as a video"});
  fs::remove(dir_.file("gelsight/Cork/press_2.mkv"));
  cv::Mat small(10, 10, CV_8UC3);
  cv::randu(small, 60, 200);  // a gel-like image, but of another size than the videos'
  cv::imwrite(dir_.file("ref.png"), small);
  refused({dir_.file("gelsight"), "-o", out(), "--reference", dir_.file("ref.png")}, {"ref.png", "10x10", "160x120"});
  refused({dir_.file("gelsight"), "-o", dir_.file("no/such/dir/g.h5")}, {"does not exist"});
  refused({dir_.file("gelsight"), "-o", out(), "--reference-frames", "3"}, {"--reference-frames", "10 to 250"});
  std::ofstream(out()) << "old";
  const CommandResult r = run_haptex({"capture", "extract", dir_.file("gelsight"), "-o", out()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("already exists"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace haptex::test
