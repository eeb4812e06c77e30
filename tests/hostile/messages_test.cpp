// Issue 11 point 6: every failure is a haptex error with exit code 2 (bad input) and a message that
// names the file, the place and the fix; never "unexpected error", a C++ exception's text or exit 1.
#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <span>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "core/h5/file.hpp"
#include "core/json/schema.hpp"
#include "core/sha256.hpp"
#include "tests/hostile/hostile_support.hpp"
#include "tests/support/mutations.hpp"
#include "tests/support/quick_models.hpp"
#include "tests/support/sample_recording.hpp"
#include "tests/support/small_pipeline.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {
namespace fs = std::filesystem;

std::string half_of(const TempDir& dir, const std::string& file, const std::string& name) {
  const std::string copy = copy_into(dir, file, name);
  fs::resize_file(copy, fs::file_size(copy) / 2);
  return copy;
}

TEST(Messages, ATruncatedHdf5FileIsBadInputWithAFixEverywhere) {
  const TempDir dir;
  const SmallPipeline& p = small_pipeline();
  const std::string r = half_of(dir, p.recordings, "r.h5"), g = half_of(dir, p.gelsight, "g.h5");
  const std::string d = half_of(dir, p.dataset, "d.h5"), m = half_of(dir, quick_model(), "m.h5");
  std::ofstream traj(dir.file("t.csv"));
  traj << "force,speed\n";
  for (int i = 0; i < 100; ++i) traj << "1,100\n";
  traj.close();
  const std::vector<std::pair<std::string, std::vector<std::string>>> runs = {
      {r, {"align", "--recordings", r, "--gelsight", p.gelsight, "-o", dir.file("o1.h5")}},
      {g, {"align", "--recordings", p.recordings, "--gelsight", g, "-o", dir.file("o2.h5")}},
      {d, {"split", d, "-o", dir.file("o.json")}},
      {d, {"info", d}},
      {d, {"info", d, "--json"}},
      {d, {"train", d, "--split", p.split, "-o", dir.file("o3.h5")}},
      {d, {"evaluate", d, "--split", p.split, "--model", quick_model(), "-o", dir.file("rep")}},
      {m, {"predict", m, "--material", small_material(), "--normal-force", "1", "--speed", "100"}},
      {m, {"render", m, "--material", small_material(), "--trajectory", dir.file("t.csv"), "-o", dir.file("o.wav")}},
      {d, {"qa", d}},
  };
  for (const auto& [file, args] : runs) {
    SCOPED_TRACE(args[0] + " " + file);
    expect_refusal(run_haptex(args), {file, "copy it again"});
  }
  EXPECT_EQ(files_named(dir.path().string(), {"o1.h5", "o2.h5", "o.json", "o3.h5", "rep", "o.wav"}), std::vector<std::string>{});
  EXPECT_EQ(partial_files(dir.path().string()), std::vector<std::string>{});
}

// A dataset whose window 3 names recording 999: train names the window; split refuses it through qa's
// window table check (review 12, F4), which `haptex qa` reports.
TEST(Messages, AWindowOfAMissingRecordingIsNamed) {
  const TempDir dir;
  const std::string d = copy_into(dir, small_pipeline().dataset, "d.h5");
  {
    Edit edit(d);
    std::vector<std::int32_t> recording = edit.dataset("windows/recording").read<std::int32_t>();
    recording.at(3) = 999;
    edit.replace<std::int32_t>("windows/recording", recording, {recording.size()});
  }
  nlohmann::json manifest = read_json(small_pipeline().split);
  manifest["dataset"]["sha256"] = sha256_file(d);
  write_json(dir.file("split.json"), manifest);
  expect_refusal(run_haptex({"split", d, "-o", dir.file("s.json")}), {d, "/windows[", "dataset.windows", "haptex qa"});
  expect_refusal(run_haptex(quick_train_args(d, dir.file("split.json"), dir.file("m.h5"))), {d, "/windows[3] (", "recording 999"});
  const CommandResult qa = run_haptex({"qa", d});
  EXPECT_EQ(qa.exit_code, 1);
  EXPECT_NE(qa.out.find("dataset.windows          error     fail"), std::string::npos) << qa.out;
}

// Review 18, F9: a press @fps of NaN or of two values is malformed (qa's layout.* fails it), so split,
// windows and train refuse the dataset although they never read the press's rate, naming the place.
TEST(Messages, AMalformedPressAttributeStopsEveryCommandThatReadsTheDataset) {
  const TempDir dir;
  const double two[] = {30.0, 60.0};
  const std::vector<std::pair<std::string, std::function<void(h5::Group&)>>> cases = {
      {"NaN", [](h5::Group& press) { press.set_attr("fps", std::nan("")); }},
      {"two values", [&two](h5::Group& press) { press.set_attr("fps", std::span<const double>(two)); }}};
  for (const auto& [what, change] : cases) {
    SCOPED_TRACE(what);
    const std::string d = copy_into(dir, small_pipeline().dataset, "d.h5");
    std::string place;
    {
      Edit edit(d);
      const std::string material = edit.group("materials").children().at(0);
      h5::Group press = edit.group("materials/" + material + "/presses/0");
      change(press);
      place = "/materials/" + material + "/presses/0/@fps";
    }
    nlohmann::json manifest = read_json(small_pipeline().split);
    manifest["dataset"]["sha256"] = sha256_file(d);
    write_json(dir.file("split.json"), manifest);
    expect_refusal(run_haptex({"split", d, "-o", dir.file("s.json")}), {d, place, "haptex qa"});
    expect_refusal(run_haptex({"windows", d, "--split", dir.file("split.json"), "-o", dir.file("w.h5")}), {d, place});
    expect_refusal(run_haptex(quick_train_args(d, dir.file("split.json"), dir.file("m.h5"))), {d, place});
    EXPECT_EQ(files_named(dir.path().string(), {"s.json", "w.h5", "m.h5"}), std::vector<std::string>{});
    fs::remove(d);
  }
}

// Names must be UTF-8; the first byte that is not is named, with the file, and nothing is written.
TEST(Messages, ANameThatIsNotUtf8IsRefusedAtTheDoor) {
  const TempDir dir;
  const fs::path xml = one_synth_recording(dir.file("s"));
  std::string text = read_recording_text(xml.string());
  const auto open = text.find("<material>") + 10;
  text.replace(open, text.find("</material>") - open, "Caf\xe9");
  write_recording_text(xml.string(), text);
  expect_refusal(run_haptex({"convert", "hatt", xml.string(), "-o", dir.file("r.h5")}), {xml.string(), "<material>", "not valid UTF-8", "byte 3", "Caf\\xe9"});
  EXPECT_FALSE(fs::exists(dir.file("r.h5")));

  const CommandResult record = run_haptex({"capture", "record", "--device", "fake:size=64x48,lockstep", "--material", "Caf\xe9",
                                           "--presses", "1", "-o", dir.file("session")});
  expect_refusal(record, {"--material", "not valid UTF-8", "byte 3"});
  EXPECT_FALSE(fs::exists(dir.file("session")));

  const fs::path material = *fs::directory_iterator(dir.file("s/gelsight"));
  fs::rename(material, material.parent_path() / "Caf\xe9");
  expect_refusal(run_haptex({"capture", "extract", dir.file("s/gelsight"), "-o", dir.file("g.h5"), "--json"}),
                 {"not valid UTF-8", "byte", "Caf\\xe9"});
  EXPECT_FALSE(fs::exists(dir.file("g.h5")));

  // A name attribute edited into a dataset: every reader of HDF5 strings refuses it.
  const std::string d = copy_into(dir, small_pipeline().dataset, "d.h5");
  {
    Edit edit(d);
    edit.remove("materials/" + small_material() + "@name");
    edit.group("materials/" + small_material()).set_attr("name", "Caf\xe9");
  }
  const std::string where = "/materials/" + small_material() + " attribute 'name'";
  expect_refusal(run_haptex({"info", d, "--json"}), {d, where, "not valid UTF-8"});
  // split's gate (qa's layout checks, review 18 F9) finds it first, and names the byte as well.
  expect_refusal(run_haptex({"split", d, "-o", dir.file("split.json")}),
                 {d, "/materials/" + small_material() + "/@name", "not valid UTF-8 (byte 3", "layout.dtype"});
  EXPECT_FALSE(fs::exists(dir.file("split.json")));
}

// Review 5, finding 11: material ids dropped every letter beyond ASCII, so "木材 1" and "金属 1" both
// became `1` (and "Café 1", "Cafè 1" both `caf_1`), and extract and convert joined each pair into one
// material without a word. Now each name keeps its own id (core/naming.hpp).
TEST(Messages, MaterialsWhoseNamesDifferOnlyBeyondAsciiStayApart) {
  const TempDir dir;
  ASSERT_EQ(run_haptex({"synth", "materials", "-n", "1", "--presses", "4", "--recordings", "4", "--seconds", "0.5", "--size", "160x120",
                        "-o", dir.file("s")}).exit_code, 0);
  const std::vector<std::string> names{"\u6728\u6750 1", "\u91d1\u5c5e 1", "Caf\u00e9 1", "Caf\u00e8 1"};
  const fs::path material = *fs::directory_iterator(dir.file("s/gelsight"));  // four presses: one video each
  // Four recordings of their own: align refuses one recording twice (it would leak between train and test).
  std::vector<fs::path> xmls(fs::directory_iterator(dir.file("s/recordings")), fs::directory_iterator());
  ASSERT_EQ(xmls.size(), names.size());
  for (std::size_t i = 0; i < names.size(); ++i) {
    const std::string text = read_recording_text(xmls[i].string());
    const auto open = text.find("<material>") + 10, length = text.find("</material>") - open;
    fs::create_directories(dir.path() / "presses" / names[i]);
    fs::copy_file(material / ("press_" + std::to_string(i) + ".avi"), dir.path() / "presses" / names[i] / "press.avi");
    fs::create_directories(dir.file("recordings"));
    write_recording_text(dir.file("recordings/" + std::to_string(i) + ".xml"), std::string(text).replace(open, length, names[i]));
  }
  for (const std::vector<std::string>& command :
       {std::vector<std::string>{"capture", "extract", dir.file("presses"), "--no-sheets", "-o", dir.file("g.h5")},
        std::vector<std::string>{"convert", "hatt", dir.file("recordings"), "-o", dir.file("r.h5")}}) {
    const CommandResult r = run_haptex(command);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(material_ids(command.back()),
              (std::vector<std::string>{"caf_u00e8_1", "caf_u00e9_1", "u6728_u6750_1", "u91d1_u5c5e_1"})) << command[1];
  }
  const CommandResult aligned = run_haptex({"align", "--recordings", dir.file("r.h5"), "--gelsight", dir.file("g.h5"), "-o", dir.file("d.h5")});
  ASSERT_EQ(aligned.exit_code, 0) << aligned.err;
  EXPECT_EQ(material_ids(dir.file("d.h5")).size(), 4u);
  const std::string qa = run_haptex({"qa", dir.file("g.h5")}).out;  // one press each: too few to train on, but well formed
  const std::string layout = qa.substr(qa.find("layout.required"), qa.find('\n', qa.find("layout.required")) - qa.find("layout.required"));
  EXPECT_NE(layout.find("pass"), std::string::npos) << qa;
}

// `cd material && haptex capture extract press_0.avi -o /abs/g.h5`: a bare name in the current folder
// (a video, ./name) is an input like any other.
// Review 9, F9: extract printed a folder's newline and tab raw in its -v lines and its "no press
// found" error, so a line split where the name did.
TEST(Messages, ExtractEscapesANewlineInAFoldersName) {
  const TempDir dir;
  const fs::path synth = fs::path(small_pipeline().recordings).parent_path() / "synth" / "gelsight" / "Woven 1";
  fs::create_directories(dir.path() / "in" / "Wo\tven\n1");
  fs::copy_file(synth / "press_0.avi", dir.path() / "in" / "Wo\tven\n1" / "press_0.avi");
  const CommandResult found = run_haptex({"-v", "capture", "extract", dir.file("in"), "--no-sheets", "-o", dir.file("g.h5")});
  ASSERT_EQ(found.exit_code, 0) << found.err;
  const CommandResult none = run_haptex({"capture", "extract", dir.file("in"), "--no-sheets", "--trigger", "1000", "-o", dir.file("n.h5")});
  EXPECT_EQ(none.exit_code, 1) << none.err;
  for (const std::string& err : {found.err, none.err}) {
    EXPECT_NE(err.find("Wo\\x09ven\\x0a1/press_0.avi: "), std::string::npos) << err;
    EXPECT_EQ(err.find("ven\n1"), std::string::npos) << err;
  }
}

TEST(Messages, RelativeInputsInTheCurrentFolderWork) {
  const TempDir dir;
  ASSERT_EQ(run_haptex({"synth", "materials", "-n", "2", "--presses", "1", "--recordings", "1", "--seconds", "0.5", "-o", dir.file("s")})
                .exit_code,
            0);
  const std::string material = dir.file("s/gelsight/Sandpaper 1");
  for (const std::string input : {"press_0.avi", "./press_0.avi"}) {
    SCOPED_TRACE(input);
    const CommandResult r = run_haptex_in(material, {"capture", "extract", input, "-o", dir.file("g.h5"), "--no-sheets", "--force"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("1 presses of 1 materials"), std::string::npos) << r.out;
  }
  const CommandResult folder = run_haptex_in(material, {"capture", "extract", ".", "-o", dir.file("g.h5"), "--no-sheets", "--force"});
  ASSERT_EQ(folder.exit_code, 0) << folder.err;
  const CommandResult info = run_haptex({"info", dir.file("g.h5")});
  EXPECT_NE(info.out.find("sandpaper_1 (Sandpaper 1)"), std::string::npos) << "named after the current folder: " << info.out;
}

// A folder no one may list, inside the folder given: the message names it, not its parent. Root
// reads any folder, so as root the command runs as nobody (setpriv).
TEST(Messages, AnUnreadableSubfolderIsNamedItself) {
  const TempDir dir;
  fs::create_directories(dir.file("recs/Secret"));
  ASSERT_EQ(run_haptex({"synth", "materials", "-n", "1", "--presses", "1", "--recordings", "1", "--seconds", "0.5", "--size", "64x48",
                        "-o", dir.file("s")}).exit_code, 0);
  fs::copy(dir.file("s/recordings"), dir.file("recs"));
  fs::permissions(dir.path(), fs::perms::all, fs::perm_options::add);
  fs::permissions(dir.file("recs"), fs::perms::all, fs::perm_options::add);
  fs::permissions(dir.file("recs/Secret"), fs::perms::none);
  std::vector<std::string> argv = {haptex_binary(), "convert", "hatt", dir.file("recs"), "-o", dir.file("r.h5")};
  if (::geteuid() == 0) {
    if (run_program({"setpriv", "--version"}).exit_code != 0) GTEST_SKIP() << "running as root without setpriv";
    argv.insert(argv.begin(), {"setpriv", "--reuid=65534", "--regid=65534", "--clear-groups"});
  }
  const CommandResult r = run_program(argv);
  fs::permissions(dir.file("recs/Secret"), fs::perms::owner_all);
  expect_refusal(r, {dir.file("recs/Secret") + ": cannot list the folder"});
}

// Review 7: 1e-40 was stored as a float32 subnormal with its digits lost, 1e-320 as 0, while 1e-400
// was refused with a 64-bit range the readers did not apply.
TEST(Messages, ANumberPastAFloatsRangeIsSaidToBeOutOfRange) {
  const TempDir dir;
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"1e-400", "out of range of the 32-bit floats haptex stores (magnitudes from 1.2e-38 to 3.4e38, or 0)"},
      {"1e-320", "under 1.2e-38"},
      {"-1e-40", "under 1.2e-38"},
  };
  for (const auto& [value, says] : cases) {
    SCOPED_TRACE(value);
    std::ofstream(dir.file("t.csv")) << "force,speed\n" << value << ",100\n";
    const CommandResult r = run_haptex({"predict", quick_model(), "--material", small_material(), "--csv", dir.file("t.csv")});
    expect_refusal(r, {dir.file("t.csv"), "line 2", says});
  }
  std::ofstream(dir.file("zero.csv")) << "force,speed\n0,100\n-0,100\n1.2e-38,100\n";
  EXPECT_EQ(run_haptex({"predict", quick_model(), "--material", small_material(), "--csv", dir.file("zero.csv")}).exit_code, 0);
}

TEST(Messages, SplitNamesTheDatasetOfAMaterialWithFourPresses) {
  const TempDir dir;
  const std::string d = copy_into(dir, small_pipeline().dataset, "d.h5");
  const std::string id = read_json(small_pipeline().split)["materials"][0]["id"];
  {
    Edit edit(d);
    edit.remove("materials/" + id + "/presses/4");
  }
  expect_refusal(run_haptex({"split", d, "-o", dir.file("s.json")}), {d, "/materials/" + id + "/presses", "4 presses"});
}

TEST(Messages, QaSaysWhichWindowStartsWhereItShouldNot) {
  const TempDir dir;
  const std::string d = copy_into(dir, small_pipeline().dataset, "d.h5");
  {
    Edit edit(d);
    std::vector<std::int64_t> start = edit.dataset("windows/start").read<std::int64_t>();
    start.at(0) = -390;
    edit.replace<std::int64_t>("windows/start", start, {start.size()});
  }
  const CommandResult r = run_haptex({"qa", d});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.out.find("window 0 of its recording starts at sample -390, expected 0"), std::string::npos) << r.out;
}

TEST(Messages, AFakeCameraOfAbsurdSizeIsRefusedAndLeavesNoFolder) {
  const TempDir dir;
  expect_refusal(run_haptex({"capture", "record", "--device", "fake:size=100000x100000", "--material", "Cork", "-o", dir.file("s")}),
                 {"--device", "size", "at most 4096x4096"});
  EXPECT_FALSE(fs::exists(dir.file("s")));
}

// Review 4: speed=1e-30 made every frame's due time overflow, and the fake spun producing frames
// without end, deaf to --seconds and to signals; fps=1e-40 ended in an internal schema error with a
// press file no session.json listed.
TEST(Messages, AFakeCameraRateOrSpeedOutOfRangeIsRefusedAndLeavesNoFolder) {
  const TempDir dir;
  for (const std::string key : {"speed=1e-30", "speed=1e-40", "speed=1000", "fps=1e-40", "fps=0.5", "fps=5000"}) {
    SCOPED_TRACE(key);
    expect_refusal(run_haptex({"capture", "record", "--device", "fake:size=160x120," + key, "--material", "Cork", "-o", dir.file("s")}),
                   {"--device", key.substr(0, key.find('=')), "from"});
    EXPECT_FALSE(fs::exists(dir.file("s")));
  }
}

// Review 5: the default fake (3280 x 2464) rendered all its frames at STREAMON, 20 s before the
// recorder's loop, which reads --seconds and Ctrl-C, first ran; it renders each when first needed now.
// The slowest is 1 frame a second: slower, every take ended as a stalled sensor (review 26, F2), and it is
// refused, naming fps and speed.
TEST(Messages, TheSlowestAndTheLargestFakeCamerasStillEndTheTakeOnTime) {
  for (const std::string device : {"fake:size=160x120,fps=1", "fake"}) {
    SCOPED_TRACE(device);
    const TempDir dir;
    const auto start = std::chrono::steady_clock::now();
    const CommandResult r = run_haptex({"capture", "record", "--device", device, "--material", "Cork", "-o", dir.file("s"), "--seconds",
                                        "1", "-q"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10));
    EXPECT_TRUE(fs::exists(dir.file("s/session.json")) || fs::exists(dir.file("s")) == false) << "a take of no press leaves no folder";
  }
}

// Review 26, F2: each key in range, fps 1 at speed 0.3 sent a frame every 3.3 s, so every take ended
// "the sensor stopped sending frames" (exit 1, no press) whatever --seconds said.
TEST(Messages, AFakeOrReplayTooSlowToRecordIsRefusedNamingFpsAndSpeed) {
  const TempDir dir;
  for (const std::string device : {"fake:size=160x120,fps=1,speed=0.3", "fake:size=160x120,speed=0.02"}) {
    SCOPED_TRACE(device);
    expect_refusal(run_haptex({"capture", "record", "--device", device, "--material", "Cork", "-o", dir.file("s")}),
                   {"--device", "speed", "frames a second, fewer than the 1 a recording takes"});
    EXPECT_FALSE(fs::exists(dir.file("s")));
  }
  ASSERT_EQ(run_haptex({"capture", "record", "--device", "fake:size=160x120,lockstep", "--material", "Cork", "--presses", "1", "-o",
                        dir.file("take"), "-q"}).exit_code, 0);
  const std::string press = dir.file("take/press_0.h5");
  expect_refusal(run_haptex({"capture", "record", "--device", "replay:" + press + ",fps=1,speed=0.3", "--material", "Cork", "-o",
                             dir.file("r")}),
                 {"--device", "speed", "fewer than the 1"});
  EXPECT_FALSE(fs::exists(dir.file("r")));
}

// Review 6: --trigger under the no-contact level wrote presses whose peak lay outside their contact
// (qa, merge and align then refused the file as damaged), and an all-black or all-white --reference
// made every frame contact; both were exit 0.
TEST(Messages, ExtractRefusesATriggerUnderTheLevelAndAFlatReference) {
  const TempDir dir;
  ASSERT_EQ(run_haptex({"synth", "materials", "-n", "1", "--presses", "1", "--recordings", "1", "--seconds", "0.5", "--size", "64x48",
                        "-o", dir.file("s")}).exit_code, 0);
  const std::string material = (*fs::directory_iterator(dir.file("s/gelsight"))).path().string();
  expect_refusal(run_haptex({"capture", "extract", material, "--trigger", "0.001", "--no-sheets", "-o", dir.file("g.h5")}),
                 {"--trigger", "is not above this source's no-contact level"});
  for (const auto& [name, colour, says] : {std::tuple{"black.png", 0, "is black"}, std::tuple{"white.png", 255, "one flat grey"}}) {
    cv::imwrite(dir.file(name), cv::Mat(48, 64, CV_8UC3, cv::Scalar::all(colour)));
    expect_refusal(run_haptex({"capture", "extract", material, "--reference", dir.file(name), "--no-sheets", "-o", dir.file("g.h5")}),
                   {dir.file(name), says});
  }
  EXPECT_FALSE(fs::exists(dir.file("g.h5")));
}

// Review 6: one frame of an MJPG video that does not decode (its JPEG states another size), next to
// the press's peak, refused the whole video (exit 2, "the frame does not decode"). Now frames that do
// not decode are never kept: a press no run of 12 decoded frames can hold is left out and said to be.
TEST(Messages, AFrameThatDoesNotDecodeBesideThePeakLeavesThePressOutNotTheVideo) {
  const TempDir dir;
  ASSERT_EQ(run_haptex({"synth", "materials", "-n", "1", "--presses", "1", "--recordings", "1", "--seconds", "0.5", "--size", "64x48",
                        "-o", dir.file("s")}).exit_code, 0);
  const fs::path video = *fs::directory_iterator(*fs::directory_iterator(dir.file("s/gelsight")));
  const CommandResult clean = run_haptex({"--json", "capture", "extract", video.string(), "--no-sheets", "-o", dir.file("clean.h5")});
  ASSERT_EQ(clean.exit_code, 0) << clean.err;
  const std::int64_t peak = nlohmann::json::parse(clean.out)["presses"][0]["peak_index"];
  std::string bytes = file_bytes(video.string());
  std::size_t sof = 0;
  for (std::int64_t frame = 0; frame <= peak - 2; ++frame) sof = bytes.find("\xFF\xC0", sof + 1);
  ASSERT_NE(sof, std::string::npos);
  bytes[sof + 5] = 0x01;  // the frame's height, high byte: 256 more rows than the video's
  const std::string damaged = dir.file("damaged.avi");
  std::ofstream(damaged, std::ios::binary) << bytes;
  const CommandResult r = run_haptex({"--json", "capture", "extract", damaged, "--material", "Cork", "--no-sheets", "-o", dir.file("g.h5")});
  EXPECT_NE(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.err.find("the frame does not decode"), std::string::npos) << r.err;
  if (r.exit_code == 0) {  // a run of 12 decoded frames holds the peak: it is kept, the damaged frame is not
    const h5::File kept = h5::File::open(dir.file("g.h5"));
    for (std::int64_t index : kept.root().open_dataset("materials/cork/presses/0/frame_indices").read<std::int64_t>()) EXPECT_NE(index, peak - 2);
  } else {
    EXPECT_NE(r.err.find("1 press(es) left out: frames around the peak do not decode"), std::string::npos) << r.err;
  }
}

// Review 5: qa refused a split manifest with a UTF-8 byte order mark that train took, and checked a
// training log as if it were a split manifest (its fields as schema errors).
TEST(Messages, QaReadsAManifestWithAByteOrderMarkAndRefusesATrainingLog) {
  const TempDir dir;
  const SmallPipeline& p = small_pipeline();
  std::ofstream(dir.file("bom.json"), std::ios::binary) << "\xEF\xBB\xBF" << file_bytes(p.split);
  const CommandResult plain = run_haptex({"qa", p.split}), bom = run_haptex({"qa", dir.file("bom.json")});
  EXPECT_EQ(bom.exit_code, plain.exit_code) << bom.err;
  EXPECT_NE(bom.out.find("verdict: clean"), std::string::npos) << bom.out << bom.err;
  std::ofstream(dir.file("m.training.json")) << R"({"format": "training-log/1", "model": "m.h5", "epochs": []})";
  expect_refusal(run_haptex({"qa", dir.file("m.training.json")}), {"/format", "is 'training-log/1', not a split manifest"});
}

// Review 6: predict's "use one of the ids haptex info lists" pointed at an info that listed none for
// a model.
TEST(Messages, InfoListsTheMaterialsAModelKnows) {
  const CommandResult r = run_haptex({"info", quick_model(), "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json doc = nlohmann::json::parse(r.out);
  EXPECT_NO_THROW(json::validate(doc, "info.schema.json", "info output"));
  std::vector<std::string> ids;
  for (const auto& m : doc["materials"]) ids.push_back(m["id"]);
  EXPECT_EQ(ids, material_ids(small_pipeline().dataset));
  EXPECT_NE(run_haptex({"info", quick_model()}).out.find(small_material() + " ("), std::string::npos);
}

// Review 6: a sensor sending only error buffers (or, in lockstep, dropping every frame) held the take
// forever, deaf to TERM; kill -9 then left an empty folder. Now no frame for 2 s ends it as a stall,
// with the manifest written. And a lockstep take with no press grew memory without bound (8.7 GB in a
// minute): the frames waiting to be scored are bounded now (totals.max_queue_depth).
TEST(Messages, ASensorSendingNoUsableFrameEndsAsAStall) {
  for (const std::string device : {"fake:size=160x120,error=100", "fake:size=160x120,error=100,lockstep", "fake:size=160x120,drop=100,lockstep"}) {
    SCOPED_TRACE(device);
    const TempDir dir;
    const CommandResult r = run_program({"timeout", "-s", "KILL", "60", haptex_binary(), "capture", "record", "--device", device, "--material",
                                         "Cork", "-o", dir.file("s"), "-q"});
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_NE(r.err.find("stopped sending frames"), std::string::npos) << r.err;
    ASSERT_TRUE(fs::exists(dir.file("s/session.json")));
    EXPECT_EQ(read_json(dir.file("s/session.json"))["ended_by"], "stalled");
  }
  const TempDir dir;
  const CommandResult r = run_program({"timeout", "-s", "KILL", "60", haptex_binary(), "capture", "record", "--device",
                                       "fake:size=160x120,lockstep,presses=0", "--material", "Cork", "-o", dir.file("s"), "--seconds", "3", "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json totals = read_json(dir.file("s/session.json"))["totals"];
  EXPECT_LE(totals["max_queue_depth"].get<int>(), 1024) << totals.dump();
  EXPECT_GT(totals["frames"].get<int>(), 1024) << "the source outran the scorer, so the bound was met: " << totals.dump();
}

// Review 6, #14: a 10-sample render said "9.55 s compute per s of vibration": under a second the
// start-up outweighs the vibration, so the time itself is given.
TEST(Messages, AShortRenderGivesItsComputeTimeNotARate) {
  const TempDir d;
  std::ofstream trajectory(d.file("t.csv"));
  trajectory << "force,speed\n";
  for (int i = 0; i < 10; ++i) trajectory << "1,100\n";
  trajectory.close();
  const CommandResult r = run_haptex({"render", quick_model(), "--material", small_material(), "--trajectory", d.file("t.csv"), "-o",
                                      d.file("v.wav")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.find("per s of vibration"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("s compute\n"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace haptex::test
