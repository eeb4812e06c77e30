// Issue 32, classes 10, 11, 13, 14, 16 and 17: values a reader must refuse, naming the file, the place
// and the fix, with exit code 2 and nothing written.
#include <gtest/gtest.h>
#include <hdf5.h>

#include "core/naming.hpp"
#include "core/sha256.hpp"

#include <algorithm>
#include <functional>
#include <iterator>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <tuple>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "tests/hostile/hostile_support.hpp"
#include "tests/support/ar_fixture.hpp"
#include "tests/support/mutations.hpp"
#include "tests/support/quick_models.hpp"
#include "tests/support/sample_recording.hpp"
#include "tests/support/small_pipeline.hpp"
#include "tests/support/temp_dir.hpp"
#include "tests/support/wav_file.hpp"

namespace haptex::test {
namespace {
namespace fs = std::filesystem;

// A CSV recording in the built-in map's columns, `rows` rows at 10 kHz, each row made by `row`.
std::string csv_recording(const TempDir& d, const std::string& name, int rows,
                          const std::function<std::string(int)>& row, const std::string& header = "time_s,accelX,accelY,accelZ,forceNormal,speed") {
  std::ofstream out(d.file(name));
  out << header << "\n";
  for (int i = 0; i < rows; ++i) out << row(i) << "\n";
  return d.file(name);
}

std::string t(int i, double step = 1e-4) { return std::to_string(i * step); }

CommandResult convert(const TempDir& d, const std::string& csv, const std::vector<std::string>& more = {}) {
  std::vector<std::string> args{"convert", "hatt", csv, "-o", d.file("r.h5")};
  args.insert(args.end(), more.begin(), more.end());
  return run_haptex(args);
}

TEST(BadValues, StampsTooCloseTogetherNameTheColumn) {
  const TempDir d;
  const std::string csv = csv_recording(d, "rig_0.csv", 2000, [](int i) {
    char time[32];
    std::snprintf(time, sizeof time, "%.12e", i * 1e-10);
    return std::string(time) + ",0.1,0.2,0.3,1,40";
  });
  expect_refusal(convert(d, csv), {csv, "column 'time_s'", "Give the times in seconds"});
  EXPECT_FALSE(fs::exists(d.file("r.h5")));
}

TEST(BadValues, AFiniteValueBeyondFloat32IsRefused) {
  const TempDir d;
  const std::string csv = csv_recording(d, "rig_0.csv", 2000, [](int i) { return t(i) + (i == 7 ? ",1e39" : ",0.1") + ",0.2,0.3,1,40"; });
  expect_refusal(convert(d, csv), {csv, "line 9", "accelX", "32-bit floats"});
  std::ofstream(d.file("traj.csv")) << "force,speed\n1,100\n1e39,100\n";
  expect_refusal(run_haptex({"predict", quick_model(), "--material", small_material(), "--csv", d.file("traj.csv")}),
                 {d.file("traj.csv"), "line 3", "32-bit floats"});
  expect_refusal(run_haptex({"render", quick_model(), "--material", small_material(), "--trajectory", d.file("traj.csv"), "-o",
                             d.file("v.wav")}),
                 {d.file("traj.csv"), "line 3", "32-bit floats"});
  EXPECT_FALSE(fs::exists(d.file("r.h5")));
  EXPECT_FALSE(fs::exists(d.file("v.wav")));
}

// Review 23, F3: each value under float32's largest, what convert derives from them beyond it: three
// axes of +-3e38 make a DFT321 magnitude up to sqrt(3) times that, a force of +-3.3e38 a low-pass
// that overshoots. Stored as inf, exit 0, and the file failed haptex's own qa.
TEST(BadValues, ADerivedChannelBeyondFloat32IsRefused) {
  const TempDir d;
  const std::string axes = csv_recording(d, "axes_0.csv", 2000, [](int i) {
    const std::string a = i % 2 ? "-3e38" : "3e38";
    return t(i) + "," + a + "," + a + "," + a + ",1,40";
  });
  expect_refusal(convert(d, axes), {axes, "DFT321", "beyond the 32-bit floats"});
  const std::string force = csv_recording(d, "force_0.csv", 2000, [](int i) { return t(i) + ",0.1,0.2,0.3," + (i % 2 ? "-3.3e38" : "3.3e38") + ",40"; });
  expect_refusal(convert(d, force), {force, "normal force low-passed", "beyond the 32-bit floats"});
  EXPECT_FALSE(fs::exists(d.file("r.h5")));
}

TEST(BadValues, AValueAndATimeInDifferentRowsAreRefused) {
  const TempDir d;
  nlohmann::json map = nlohmann::json::parse(std::ifstream(std::string(HAPTEX_SCHEMA_DIR) + "/hatt-recording-map.json"));
  map["csv_channel_times"] = {{"force_normal", "t_force"}};
  std::ofstream(d.file("map.json")) << map.dump();
  // Row 10 has a force without its time, row 11 a time without its force: the counts agree.
  const std::string csv = csv_recording(
      d, "rig_0.csv", 2000,
      [](int i) {
        const std::string force = i == 10 ? ",,2" : i == 11 ? "," + t(i) + "," : i % 2 ? ",," : "," + t(i) + ",1";
        return t(i) + ",0.1,0.2,0.3" + force + ",40";
      },
      "time_s,accelX,accelY,accelZ,t_force,forceNormal,speed");
  expect_refusal(convert(d, csv, {"--map", d.file("map.json")}), {csv, "line 12", "forceNormal", "t_force"});
}

// Review 9, C2: a map that puts two channels on one column, or a time column on a channel's, was refused
// only when a CSV was read, naming the CSV and an impossible count ("has 0 values").
TEST(BadValues, AFieldMapThatGivesTwoThingsOneColumnIsRefusedNamingTheMap) {
  const TempDir d;
  const std::string csv = csv_recording(d, "rig_0.csv", 2000, [](int i) { return t(i) + ",0.1,0.2,0.3,1,40"; });
  const std::vector<std::tuple<std::string, std::string, std::string>> clashes = {
      {"/channels/speed", "forceNormal", "channels.speed"},
      {"/csv_time_column", "accelX", "csv_time_column"},
      {"/csv_channel_times", "", "csv_channel_times.force_normal"}};
  for (const auto& [pointer, column, where] : clashes) {
    SCOPED_TRACE(where);
    nlohmann::json map = nlohmann::json::parse(std::ifstream(std::string(HAPTEX_SCHEMA_DIR) + "/hatt-recording-map.json"));
    if (column.empty())
      map["csv_channel_times"] = {{"force_normal", "forceNormal"}};
    else
      map[nlohmann::json::json_pointer(pointer)] = column;
    std::ofstream(d.file("map.json"), std::ios::trunc) << map.dump();
    const CommandResult r = convert(d, csv, {"--map", d.file("map.json")});
    expect_refusal(r, {d.file("map.json") + ": " + where});
    EXPECT_EQ(r.err.find(csv), std::string::npos) << "the map is at fault, not the CSV";
  }
}

// Review 10, F8: a channel's own time column in milliseconds, beside a main one in seconds, was taken:
// the overlap kept the channel's first 2 ms, stretched over the 2 s recording.
TEST(BadValues, AChannelClockInAnotherUnitIsRefused) {
  const TempDir d;
  nlohmann::json map = nlohmann::json::parse(std::ifstream(std::string(HAPTEX_SCHEMA_DIR) + "/hatt-recording-map.json"));
  map["csv_channel_times"] = {{"force_normal", "t_force"}, {"speed", "t_force"}};
  std::ofstream(d.file("map.json")) << map.dump();
  for (const double unit : {1.0, 1000.0}) {
    SCOPED_TRACE(unit);
    const std::string csv = csv_recording(
        d, "rig_0.csv", 6000,
        [&](int i) {
          const std::string force = i % 10 ? ",," : "," + std::to_string(i * 1e-4 * unit) + ",1.5";
          return t(i) + ",0.1,0.2,0.3" + force + (i % 10 ? "," : ",40");
        },
        "time_s,accelX,accelY,accelZ,t_force,forceNormal,speed");
    const CommandResult r = convert(d, csv, {"--map", d.file("map.json"), "--force"});
    if (unit == 1.0)
      EXPECT_EQ(r.exit_code, 0) << r.err;
    else
      expect_refusal(r, {csv, "column 't_force'", "998.5 times the 0.5999 s of column 'time_s'", "Give every time column in seconds"});
  }
}

TEST(BadValues, EvaluateRefusesATruthBeyondAnyVibration) {
  const SmallPipeline& p = small_pipeline();
  for (const std::string what : {"noise", "spectrum"}) {
    SCOPED_TRACE(what);
    const TempDir d;
    const std::string truth = d.file("truth.h5");
    fs::copy_file(p.truth, truth);
    {
      Edit edit(truth);
      if (what == "noise") {
        edit.root().set_attr("accel_noise_m_s2", 1e300);
      } else {
        const std::string material = material_ids(truth).front();
        edit.change_floats("materials/" + material + "/spectrum", [](std::vector<float>& v) { v[5] = 1e30f; });
      }
    }
    expect_refusal(run_haptex({"evaluate", p.dataset, "--split", p.split, "--model", quick_model(), "--truth", truth, "-o",
                               d.file("rep")}),
                   {truth, what == "noise" ? "/@accel_noise_m_s2" : "/spectrum", "up to"});
    EXPECT_FALSE(fs::exists(d.file("rep")));
  }
}

// Review 5: a press file whose every JPEG states 60000x60000 was "no press found" to extract (exit 1,
// "give a lower --trigger") and replayed as 320x240 with no press (exit 0). Damaged input: exit 2.
TEST(BadValues, APressFileOfWhichNoFrameDecodesIsRefused) {
  const TempDir d;
  ASSERT_EQ(run_haptex({"capture", "record", "--device", "fake:size=160x120,lockstep", "--material", "Cork", "--presses", "1", "-o",
                        d.file("s")}).exit_code, 0);
  const std::string press = d.file("big.h5");
  fs::copy_file(d.file("s/press_0.h5"), press);
  {
    Edit edit(press);
    const std::size_t frames = std::size_t(edit.dataset("frames").shape().at(0));
    for (std::size_t i = 0; i < frames; ++i)
      edit.change_image("frames", i, [](std::vector<std::uint8_t>& jpeg) {
        for (std::size_t k = 0; k + 8 < jpeg.size(); ++k)
          if (jpeg[k] == 0xFF && jpeg[k + 1] == 0xC0) {  // the frame header: height, width at 5..8
            jpeg[k + 5] = 0xEA, jpeg[k + 6] = 0x60, jpeg[k + 7] = 0xEA, jpeg[k + 8] = 0x60;
            break;
          }
      });
  }
  expect_refusal(run_haptex({"capture", "extract", press, "--no-sheets", "-o", d.file("g.h5")}), {press, "no frame of it decodes"});
  expect_refusal(run_haptex({"capture", "record", "--device", "replay:" + press + ",lockstep", "--material", "Cork", "-o", d.file("r")}),
                 {press, "/frames", "holds no image of the press file's 160x120 frames"});
  EXPECT_FALSE(fs::exists(d.file("g.h5")));
  EXPECT_FALSE(fs::exists(d.file("r")));
}

// Review 6: a truth.h5 of another synth run (it knows none of the dataset's recordings) was noted,
// and the models were still compared with its noise-free spectra of other recordings (exit 0).
TEST(BadValues, EvaluateRefusesATruthOfAnotherRun) {
  const SmallPipeline& p = small_pipeline();
  const TempDir d;
  const std::string truth = d.file("truth.h5");
  fs::copy_file(p.truth, truth);
  {
    Edit edit(truth);
    for (const std::string& material : material_ids(truth)) {
      h5::Group recordings = edit.group("materials/" + material + "/recordings");
      for (const std::string& k : recordings.children()) {
        edit.remove("materials/" + material + "/recordings/" + k + "@source_sha256");
        recordings.open_group(k).set_attr("source_sha256", sha256_hex(std::string("another run ") + material + k));
      }
    }
  }
  expect_refusal(run_haptex({"evaluate", p.dataset, "--split", p.split, "--model", quick_model(), "--truth", truth, "-o", d.file("rep")}),
                 {truth, "knows none of the test recordings", "another synth run"});
  EXPECT_FALSE(fs::exists(d.file("rep")));
}

// A take of one press from the fake camera into `session`, as a user records one.
bool record_one_press(const std::string& session) {
  return run_haptex({"capture", "record", "--device", "fake:size=160x120,lockstep", "--material", "Cork", "--presses", "1", "-o", session})
             .exit_code == 0;
}

TEST(BadValues, ReplayRefusesAPressFileWithoutAFrameRate) {
  const TempDir d;
  ASSERT_TRUE(record_one_press(d.file("s")));
  for (const double fps : {std::nan(""), double(INFINITY), 1e-300}) {
    SCOPED_TRACE(fps);
    const std::string press = d.file("p.h5");
    fs::copy_file(d.file("s/press_0.h5"), press, fs::copy_options::overwrite_existing);
    Edit(press).root().set_attr("fps", fps);
    expect_refusal(run_haptex({"capture", "record", "--device", "replay:" + press, "--material", "Cork", "-o", d.file("r")}),
                   {press, "/@fps"});
    EXPECT_FALSE(fs::exists(d.file("r")));
  }
}

// Review 12, F1: a 27 MB press file declaring 30000 x 30000 frames (and a /reference of that size)
// cost extract 8 GB before it was refused. The declared size is refused before anything is read.
TEST(BadValues, APressFileDeclaringFramesOver64MegapixelsIsRefusedAtOnce) {
  const TempDir d;
  ASSERT_TRUE(record_one_press(d.file("s")));
  const std::string press = d.file("p.h5");
  fs::copy_file(d.file("s/press_0.h5"), press);
  {
    Edit edit(press);
    edit.root().set_attr("width", std::int64_t(30000));
    edit.root().set_attr("height", std::int64_t(30000));
  }
  expect_refusal(run_haptex({"capture", "extract", press, "--no-sheets", "-o", d.file("g.h5")}), {press, "/@width", "over 64 megapixels"});
  expect_refusal(run_haptex({"capture", "record", "--device", "replay:" + press, "--material", "Cork", "-o", d.file("r")}), {press});
  EXPECT_FALSE(fs::exists(d.file("g.h5")));
}

// Review 9, F1: extraction used a press file's recorder figures as they were: a NaN trigger cut one
// press in two (exit 0), an infinite one said "no press found" (exit 1).
TEST(BadValues, ExtractRefusesAPressFileWithDamagedRecorderFigures) {
  const TempDir d;
  ASSERT_TRUE(record_one_press(d.file("s")));
  const std::vector<std::pair<const char*, double>> damaged = {
      {"trigger", std::nan("")}, {"trigger", 1e39}, {"trigger", -1}, {"trigger", 0}, {"trigger", 1e-40},
      {"pixel_threshold", std::nan("")}, {"pixel_threshold", -5}, {"noise", INFINITY}, {"no_contact_level", 1e39}};
  for (const auto& [name, value] : damaged) {
    SCOPED_TRACE(std::string(name) + " " + std::to_string(value));
    const std::string press = d.file("p.h5");
    fs::copy_file(d.file("s/press_0.h5"), press, fs::copy_options::overwrite_existing);
    Edit(press).root().set_attr(name, value);
    expect_refusal(run_haptex({"capture", "extract", press, "--no-sheets", "-o", d.file("g.h5")}), {press, std::string("/@") + name});
    EXPECT_FALSE(fs::exists(d.file("g.h5")));
  }
  EXPECT_EQ(run_haptex({"capture", "extract", d.file("s/press_0.h5"), "--no-sheets", "-o", d.file("g.h5")}).exit_code, 0);
}

// Review 9, F7: a press file whose stated counts disagree with its frames, whose clock or counter runs
// back, or whose reference is not the frame size was replayed (and most of them extracted).
TEST(BadValues, APressFileWhoseCountsDisagreeWithItsFramesIsRefused) {
  const TempDir d;
  ASSERT_TRUE(record_one_press(d.file("s")));
  const std::int64_t frames = std::int64_t(h5::File::open(d.file("s/press_0.h5")).root().open_dataset("frames").shape().at(0));
  const std::vector<std::pair<std::string, std::function<void(Edit&)>>> damaged = {
      {"/@samples", [](Edit& e) { e.root().set_attr("samples", std::int64_t(1e12)); }},
      {"/timestamp_ns", [](Edit& e) {
         e.remove("timestamp_ns");
         e.root().write<std::int64_t>("timestamp_ns", std::vector<std::int64_t>(10, 1));
       }},
      {"/contrast", [](Edit& e) {
         e.remove("contrast");
         e.root().write<float>("contrast", std::vector<float>(3, 1.f));
       }},
      {"/@peak_frame", [](Edit& e) { e.root().set_attr("peak_frame", std::int64_t(99999)); }},
      {"/@peak_frame", [](Edit& e) { e.root().set_attr("peak_frame", std::int64_t(-5)); }},
      {"/@contact_last", [frames](Edit& e) {
         e.root().set_attr("contact_first", frames - 1);
         e.root().set_attr("contact_last", std::int64_t(0));
       }},
      // Clocks and counters that run back, and control lists that are not the JSON the layout states.
      {"/timestamp_ns[1]", [frames](Edit& e) {
         std::vector<std::int64_t> backwards(std::size_t(frames), 0);
         for (std::int64_t i = 0; i < frames; ++i) backwards[std::size_t(i)] = (frames - i) * 33333333;
         e.replace<std::int64_t>("timestamp_ns", backwards, {std::size_t(frames)});
       }},
      {"/timestamp_ns[1]", [frames](Edit& e) {
         e.replace<std::int64_t>("timestamp_ns", std::vector<std::int64_t>(std::size_t(frames), 5), {std::size_t(frames)});
       }},
      {"/sequence[2]", [frames](Edit& e) {
         std::vector<std::uint32_t> sequence(static_cast<std::size_t>(frames));
         for (std::size_t i = 0; i < sequence.size(); ++i) sequence[i] = std::uint32_t(i == 2 ? 0 : 10 + i);
         e.replace<std::uint32_t>("sequence", sequence, {std::size_t(frames)});
       }},
      {"/@locked_controls", [](Edit& e) { e.root().set_attr("locked_controls", std::string("[{\"id\":")); }},
      {"/@missing_controls", [](Edit& e) { e.root().set_attr("missing_controls", std::string("[1, 2]")); }},
      {"/reference", [](Edit& e) { e.replace<std::uint8_t>("reference", std::vector<std::uint8_t>(300, 7), {10, 10, 3}); }},
  };
  for (const auto& [where, damage] : damaged) {
    SCOPED_TRACE(where);
    const std::string press = d.file("p.h5");
    fs::copy_file(d.file("s/press_0.h5"), press, fs::copy_options::overwrite_existing);
    {
      Edit e(press);
      damage(e);
    }
    expect_refusal(run_haptex({"capture", "extract", press, "--no-sheets", "-o", d.file("g.h5")}), {press, where});
    expect_refusal(run_haptex({"capture", "record", "--device", "replay:" + press + ",lockstep", "--material", "Cork", "-o", d.file("r")}),
                   {press, where});
    EXPECT_FALSE(fs::exists(d.file("g.h5")));
    EXPECT_FALSE(fs::exists(d.file("r")));
  }
}

// Review 10, F6: a press file whose stored reference is black or one flat grey was used (every frame
// then contact; the peak score doubled), while the same image as --reference is refused.
TEST(BadValues, ExtractRefusesABlankStoredReference) {
  const TempDir d;
  ASSERT_TRUE(record_one_press(d.file("s")));
  for (const int value : {0, 128, 255}) {
    SCOPED_TRACE(value);
    const std::string press = d.file("p.h5");
    fs::copy_file(d.file("s/press_0.h5"), press, fs::copy_options::overwrite_existing);
    {
      Edit e(press);
      const h5::Shape shape = e.dataset("reference").shape();
      e.replace<std::uint8_t>("reference", std::vector<std::uint8_t>(shape[0] * shape[1] * shape[2], std::uint8_t(value)), shape);
    }
    expect_refusal(run_haptex({"capture", "extract", press, "--no-sheets", "-o", d.file("g.h5")}),
                   {press, "/reference", value == 0 ? "is black" : "one flat grey", "Record the press again"});
    EXPECT_FALSE(fs::exists(d.file("g.h5")));
  }
}

// Review 10, F5: a material name of 300 characters passed every reader, then split and extract failed
// at their end ("File name too long", exit 1). Its id is refused where it comes in, and qa fails it.
TEST(BadValues, AMaterialNameTooLongForAFileNameIsRefusedWhereItComesIn) {
  const TempDir d;
  const std::string too_long(101, 'm'), longest(100, 'm');
  expect_refusal(run_haptex({"capture", "record", "--device", "fake:size=160x120,lockstep", "--material", too_long, "--presses", "1", "-o",
                             d.file("s")}),
                 {"--material", "makes a material id of 101 bytes, longer than the 100 haptex takes", "shorter name"});
  EXPECT_FALSE(fs::exists(d.file("s")));
  ASSERT_EQ(run_haptex({"capture", "record", "--device", "fake:size=160x120,lockstep", "--material", longest, "--presses", "1", "-o",
                        d.file("s"), "-q"}).exit_code, 0);
  EXPECT_EQ(run_haptex({"capture", "extract", d.file("s"), "-o", d.file("g.h5"), "-q"}).exit_code, 0) << "100 bytes make every file name";
  expect_refusal(run_haptex({"capture", "extract", d.file("s"), "--material", too_long, "-o", d.file("g2.h5")}),
                 {"--material", "101 bytes"});
  // A dataset holding such an id: qa fails it, split refuses it before any work.
  const std::string dataset = d.file("d.h5");
  fs::copy_file(small_pipeline().dataset, dataset);
  {
    Edit e(dataset);
    const std::string from = "materials/" + material_ids(dataset).front(), to = "materials/" + std::string(101, 'w');
    ASSERT_GE(H5Lmove(e.root().id(), from.c_str(), e.root().id(), to.c_str(), H5P_DEFAULT, H5P_DEFAULT), 0);
    std::vector<std::string> ids = e.dataset("windows/materials").read_strings();
    ids.front() = std::string(101, 'w');
    e.remove("windows/materials");
    e.group("windows").write_strings("materials", ids);
  }
  const CommandResult qa = run_haptex({"qa", dataset});
  EXPECT_EQ(qa.exit_code, 1);
  EXPECT_NE(qa.out.find("is a material id of 101 bytes, longer than the 100 haptex takes"), std::string::npos) << qa.out;
  expect_refusal(run_haptex({"split", dataset, "-o", d.file("split.json")}), {dataset, "101 bytes"});
  EXPECT_FALSE(fs::exists(d.file("split.json")));
}

// Review 23, F1: synth hatt took a model file's <material> as it was: an empty name reached HDF5 (exit 1
// naming truth.h5), a 150-byte id made a set convert hatt refuses.
TEST(BadValues, SynthHattHoldsAModelsMaterialNameToTheIdRules) {
  const TempDir d;
  std::string accents;  // 20 letters, a 119-byte id: "u00e9_u00e9_..."
  for (int i = 0; i < 20; ++i) accents += "\u00e9";
  for (const std::string& name : {std::string(), std::string("!!!"), std::string(150, 'T'), accents}) {
    const std::string folder = d.file("m" + std::to_string(name.size()));
    fs::create_directories(folder);
    std::string xml = kArFixtureXml;
    xml.replace(xml.find("Fixture"), 7, name);
    std::ofstream(folder + "/Models_Fixture.xml") << xml;
    expect_refusal(run_haptex({"synth", "hatt", "--models", folder, "-o", d.file("out"), "--recordings", "1", "--seconds", "0.5"}),
                   {folder + "/Models_Fixture.xml", "<material>"});
    EXPECT_FALSE(fs::exists(d.file("out"))) << name;
  }
}

// Review 11, F3: haptex view showed a dataset whose recording holds 7 samples where 30 000 are
// stated, which qa fails. It reads as strictly as merge and align.
TEST(BadValues, ViewRefusesADatasetQaFails) {
  const TempDir d;
  const std::string dataset = d.file("d.h5");
  fs::copy_file(small_pipeline().dataset, dataset);
  {
    Edit e(dataset);
    const std::string accel = "materials/" + material_ids(dataset).front() + "/recordings/0/accel";
    e.replace<float>(accel, std::vector<float>(7, 0.5f), {7});
  }
  expect_refusal(run_haptex({"view", dataset, "-o", d.file("site")}), {dataset, "layout.shape"});
  EXPECT_FALSE(fs::exists(d.file("site")));
}

// Review 6, #9: an AVI whose headers state no frame rate was replayed at FFmpeg's guess of 25 fps,
// and extraction stored that guess as the source's rate.
TEST(BadValues, AnAviThatStatesNoFrameRateIsNotGivenOne) {
  const TempDir d;
  const fs::path synth = fs::path(small_pipeline().recordings).parent_path() / "synth" / "gelsight";
  const std::string avi = d.file("no_rate.avi");
  fs::copy_file(synth / "Woven 1" / "press_0.avi", avi);
  std::string bytes = file_bytes(avi);
  const std::size_t avih = bytes.find("avih"), strh = bytes.find("strh");
  ASSERT_NE(avih, std::string::npos);
  ASSERT_TRUE(strh != std::string::npos && bytes.compare(strh + 8, 4, "vids") == 0);
  bytes.replace(avih + 8, 4, std::string(4, '\0'));   // dwMicroSecPerFrame
  bytes.replace(strh + 8 + 24, 4, std::string(4, '\0'));  // dwRate
  std::ofstream(avi, std::ios::binary) << bytes;
  expect_refusal(run_haptex({"capture", "record", "--device", "replay:" + avi + ",lockstep", "--material", "Cork", "-o", d.file("r")}),
                 {avi, "does not say its frame rate", "fps=N"});
  EXPECT_FALSE(fs::exists(d.file("r")));
  const CommandResult given = run_haptex({"capture", "record", "--device", "replay:" + avi + ",lockstep,fps=30", "--material", "Cork",
                                          "-o", d.file("r")});
  EXPECT_EQ(given.exit_code, 0) << given.err;
  ASSERT_EQ(run_haptex({"capture", "extract", avi, "--material", "Cork", "-o", d.file("g.h5"), "--no-sheets"}).exit_code, 0);
  if (!python_has("h5py")) GTEST_SKIP() << "python3-h5py is not installed (make deps installs it)";
  const CommandResult stored = run_python({"-c", "import h5py,sys; print('fps' in h5py.File(sys.argv[1])['materials/cork/presses/0'].attrs)",
                                           d.file("g.h5")});
  EXPECT_EQ(stored.out, "False\n") << stored.err;  // the source states none (schemas/hdf5-layout.md)
}

TEST(BadValues, APredictCsvWithExtraFieldsOrTwoForceColumnsIsRefused) {
  const TempDir d;
  std::ofstream(d.file("extra.csv")) << "force,speed\n1,100\n1,100,7\n";
  std::ofstream(d.file("twice.csv")) << "force,speed,force_n\n1,100,2\n";
  expect_refusal(run_haptex({"predict", quick_model(), "--material", small_material(), "--csv", d.file("extra.csv")}),
                 {"extra.csv", "line 3", "3 fields"});
  expect_refusal(run_haptex({"predict", quick_model(), "--material", small_material(), "--csv", d.file("twice.csv")}),
                 {"twice.csv", "line 1", "force and force_n"});
}

TEST(BadValues, AFileOfANewerFormatIsCalledNewer) {
  const TempDir d;
  const std::string dataset = d.file("d.h5");
  fs::copy_file(small_pipeline().dataset, dataset);
  Edit(dataset).root().set_attr("haptex_format", "dataset/5");
  expect_refusal(run_haptex({"split", dataset, "-o", d.file("s.json")}), {dataset, "dataset/5", "newer haptex"});
  expect_refusal(run_haptex({"qa", dataset}), {dataset, "dataset/5", "newer haptex"});
  // JSON formats too (issue 32, second review): a split/2 manifest is newer, not a schema failure.
  nlohmann::json manifest = read_json(small_pipeline().split);
  manifest["format"] = "split/2";
  write_json(d.file("s2.json"), manifest);
  const CommandResult qa = run_haptex({"qa", d.file("s2.json")});  // qa reports it as its failed split.schema check
  EXPECT_EQ(qa.exit_code, 1) << qa.err;
  EXPECT_NE(qa.out.find("/format: is split/2, written by a newer haptex"), std::string::npos) << qa.out;
  expect_refusal(run_haptex({"windows", small_pipeline().dataset, "--split", d.file("s2.json"), "-o", d.file("w.h5")}),
                 {"split/2", "newer haptex"});
}

// JSON that nests 100000 deep crashed every reader (a recursive walk ran out of stack), and 1e400
// came out as a raw library exception naming no file (issue 32, review 2).
TEST(BadValues, JsonThatNestsTooDeepOrOverflowsIsRefusedNamingTheFile) {
  const SmallPipeline& p = small_pipeline();
  const TempDir d;
  std::ofstream(d.file("deep.json")) << std::string(100000, '[') << std::string(100000, ']');
  std::ofstream(d.file("deep_object.json")) << "{\"format\": \"split/1\", \"a\": " << std::string(100000, '[') << std::string(100000, ']') << "}";
  std::ofstream(d.file("huge.json")) << "{\"format\": \"split/1\", \"sections\": 1e400}";
  for (const std::string& bad : {d.file("deep.json"), d.file("deep_object.json"), d.file("huge.json")}) {
    SCOPED_TRACE(bad);
    expect_refusal(run_haptex({"windows", p.dataset, "--split", bad, "-o", d.file("w.h5")}), {bad});
  }
  expect_refusal(run_haptex({"align", "--recordings", p.recordings, "--gelsight", p.gelsight, "--names", d.file("deep.json"), "-o",
                             d.file("a.h5")}),
                 {d.file("deep.json")});
  expect_refusal(run_haptex({"capture", "devices", "--sensors", d.file("huge.json")}), {d.file("huge.json")});
  expect_refusal(run_haptex({"qa", d.file("deep_object.json")}), {"nests deeper than 64 levels"});
  expect_refusal(run_haptex({"qa", d.file("huge.json")}), {"1e400", "64-bit floats"});
}

// A NUL inside a JSON string is refused where it is, not cut off downstream (issue 32, second review).
TEST(BadValues, ANulInAManifestNameIsRefused) {
  const TempDir d;
  nlohmann::json manifest = read_json(small_pipeline().split);
  manifest["materials"][0]["name"] = std::string("Sand\0paper", 10);
  write_json(d.file("nul.json"), manifest);
  expect_refusal(run_haptex({"qa", d.file("nul.json")}), {d.file("nul.json"), "/materials/0/name", "NUL"});
  expect_refusal(run_haptex({"windows", small_pipeline().dataset, "--split", d.file("nul.json"), "-o", d.file("w.h5")}),
                 {"/materials/0/name", "NUL"});
}

// Review 15, R5 and R6: `"sections": 1000000000` made qa, windows, train and evaluate allocate until the
// OOM killer came (24 GB), and 20 000 repeats of one section number took the schema check 24 GB. Both
// are refused at once, naming the place.
TEST(BadValues, AManifestsSizesAndRepeatsAreBoundedBeforeAnyWork) {
  const TempDir d;
  const auto refused = [&](const std::string& name, const nlohmann::json& manifest, const std::vector<std::string>& says) {
    write_json(d.file(name), manifest);
    for (const std::vector<std::string>& args : {std::vector<std::string>{"timeout", "60", haptex_binary(), "windows", small_pipeline().dataset,
                                                                          "--split", d.file(name), "-o", d.file("w.h5")},
                                                 {"timeout", "60", haptex_binary(), "qa", d.file(name)}}) {
      const CommandResult r = run_program(args);
      EXPECT_NE(r.exit_code, 124) << "ended by the time limit";
      EXPECT_TRUE(r.exit_code == 1 || r.exit_code == 2) << r.exit_code << r.err;
      for (const std::string& s : says) EXPECT_NE((r.out + r.err).find(s), std::string::npos) << s << "\n" << r.out << r.err;
    }
    EXPECT_FALSE(fs::exists(d.file("w.h5")));
  };
  nlohmann::json sections = read_json(small_pipeline().split);
  sections["parameters"]["sections"] = 1000000000;
  refused("sections.json", sections, {"/parameters/sections", "is 1000000000, more than the 10000 haptex split allows"});
  nlohmann::json repeats = read_json(small_pipeline().split);
  repeats["materials"][0]["sections"]["train"] = std::vector<int>(20000, 0);
  refused("repeats.json", repeats, {"/materials/0/sections/train", "lists 20000 numbers, more than the 10000"});
  repeats["materials"][0]["sections"]["train"] = std::vector<int>(5000, 1);
  refused("twice.json", repeats, {"/materials/0/sections/train", "lists 1 twice"});
  // 300 000 distinct press numbers: the schema check compared every pair (4.5e10 comparisons).
  nlohmann::json distinct = read_json(small_pipeline().split);
  std::vector<int> presses(300000);
  for (int i = 0; i < 300000; ++i) presses[std::size_t(i)] = i;
  distinct["materials"][0]["presses"]["train"] = presses;
  refused("distinct.json", distinct, {});
  // Review 23, F7: a 200 000-letter id crashed every reader (std::regex recursing once per character).
  nlohmann::json long_id = read_json(small_pipeline().split);
  long_id["materials"][0]["id"] = std::string(200000, 'a');
  refused("long_id.json", long_id, {"/materials/0/id", "is a text of 200000 bytes where an id"});
}

// A key given twice was kept as the last one without a word, in every JSON reader (issue 32, reviews 5
// and 6): the CSV forms refuse a column given twice, and readers differ in which of the two they keep.
TEST(BadValues, AJsonKeyGivenTwiceIsRefusedWhereItIs) {
  const TempDir d;
  std::string text = read_json(small_pipeline().split).dump();
  const std::size_t first_material = text.find("\"materials\":[{");
  ASSERT_NE(first_material, std::string::npos);
  text.insert(first_material + std::string("\"materials\":[{").size(), "\"name\":\"Other\",");
  std::ofstream(d.file("twice.json")) << text;
  expect_refusal(run_haptex({"qa", d.file("twice.json")}), {d.file("twice.json"), "/materials/0/name", "given twice"});
  expect_refusal(run_haptex({"windows", small_pipeline().dataset, "--split", d.file("twice.json"), "-o", d.file("w.h5")}),
                 {"/materials/0/name", "given twice"});
  EXPECT_FALSE(std::filesystem::exists(d.file("w.h5")));
}

TEST(BadValues, InfoShowsControlCharactersEscaped) {
  const TempDir d;
  const std::string dataset = d.file("d.h5");
  fs::copy_file(small_pipeline().dataset, dataset);
  const std::string material = material_ids(dataset).front();
  // Review 4, #7: U+202E RIGHT-TO-LEFT OVERRIDE and U+2028 LINE SEPARATOR were printed as they were.
  Edit(dataset).group("materials/" + material).set_attr("name", "felt\x1b]0;pwned\x07\x1b[2J \u202eRLO \u2028LS \u0085NEL \u00adSHY \U000E0041TAG");
  const CommandResult r = run_haptex({"info", dataset});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.find('\x1b'), std::string::npos) << "an escape sequence reached the terminal";
  EXPECT_NE(r.out.find("felt\\x1b]0;pwned\\x07"), std::string::npos) << r.out;
  for (const char* raw : {"\u202e", "\u2028", "\u0085", "\u00ad", "\U000E0041"}) EXPECT_EQ(r.out.find(raw), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\\u202eRLO \\u2028LS \\u0085NEL \\u00adSHY \\U000e0041TAG"), std::string::npos) << r.out;
}

// Review 16, F5: DEL went out as \x7f (and a tag character as \U000e0041), which JSON does not have,
// so `info --json` printed a document no JSON reader takes. The name now comes back as stored.
TEST(BadValues, JsonOutputKeepsEveryCharacterOfANameAsJson) {
  const TempDir d;
  const std::string dataset = d.file("d.h5");
  fs::copy_file(small_pipeline().dataset, dataset);
  const std::string material = material_ids(dataset).front();
  const std::string name = "felt\x7f \x1b[2J \u202e \u0085 \U000E0041 end";
  Edit(dataset).group("materials/" + material).set_attr("name", name);
  const CommandResult r = run_haptex({"info", dataset, "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.find('\x7f'), std::string::npos) << "a raw DEL reached the terminal";
  nlohmann::json doc;
  ASSERT_NO_THROW(doc = nlohmann::json::parse(r.out)) << r.out;
  EXPECT_EQ(doc["materials"][0]["name"], name);
}

// Review 15, R3: a dataset compressed with a filter haptex's HDF5 lacks (h5py's lzf) was called
// truncated or damaged ("copy it again"). It is named, with how to store it instead.
TEST(BadValues, ACompressionFilterHDF5LacksIsNamed) {
  if (!python_has("h5py")) GTEST_SKIP() << "python3-h5py is not installed (make deps installs it)";
  const TempDir d;
  const std::string copy = copy_into(d, small_pipeline().recordings, "lzf.h5");
  const CommandResult made = run_python({"-c",
                                         "import h5py,sys\n"
                                         "f=h5py.File(sys.argv[1],'r+'); found=[]\n"
                                         "f.visititems(lambda n,o: found.append(n) if isinstance(o,h5py.Dataset) and o.ndim==1 and o.size>100 and o.dtype.kind=='f' else None)\n"
                                         "n=found[0]; data=f[n][()]; attrs=dict(f[n].attrs); del f[n]\n"
                                         "f.create_dataset(n, data=data, compression='lzf', chunks=True)\n"
                                         "[f[n].attrs.__setitem__(k,v) for k,v in attrs.items()]\n"
                                         "print(n)",
                                         copy});
  ASSERT_EQ(made.exit_code, 0) << made.err;
  expect_refusal(run_haptex({"qa", copy}), {copy, "HDF5 filter 32000", "lzf", "compression='gzip'"});
}

// Review 15, R12: qa decoded a press's frames before comparing their headers with the press's size,
// so 12 frames whose headers (JPEG there, PNG here) claim 8192 x 8192 (64 megapixels, at the limit) took 3.6 GB and
// ended in "unexpected error: OpenCV ... Insufficient memory". Under a 2 GB address space it now
// reports the frames.
TEST(BadValues, QaDecodesNoFrameLargerThanItsPressStates) {
  if (!python_has("h5py, numpy")) GTEST_SKIP() << "python3-h5py is not installed (make deps installs it)";
  const TempDir d;
  const std::string copy = copy_into(d, small_pipeline().dataset, "huge_frames.h5");
  cv::Mat frame(120, 160, CV_8UC3, cv::Scalar(90, 120, 150));
  std::vector<std::uint8_t> jpeg;
  ASSERT_TRUE(cv::imencode(".jpg", frame, jpeg));
  const std::uint8_t marker[] = {0xFF, 0xC0};
  const auto sof = std::search(jpeg.begin(), jpeg.end(), std::begin(marker), std::end(marker));
  ASSERT_NE(sof, jpeg.end());
  for (int k : {5, 7}) sof[k] = 0x20, sof[k + 1] = 0;  // height and width: 8192
  std::ofstream(d.file("huge.jpg"), std::ios::binary).write(reinterpret_cast<const char*>(jpeg.data()), std::streamsize(jpeg.size()));
  // The first press's frames become 12 such JPEGs, as a JPEG-storing capture would hold them.
  const CommandResult made = run_python({"-c",
                                         "import h5py,sys,numpy as np\n"
                                         "f=h5py.File(sys.argv[1],'r+'); m=sorted(f['materials'])[0]; p=f['materials'][m]['presses']['0']\n"
                                         "attrs=dict(p['frames'].attrs); n=len(p['frames']); del p['frames']\n"
                                         "b=np.frombuffer(open(sys.argv[2],'rb').read(),np.uint8)\n"
                                         "d=p.create_dataset('frames',(n,),dtype=h5py.vlen_dtype(np.uint8))\n"
                                         "for i in range(n): d[i]=b\n"
                                         "[d.attrs.__setitem__(k,v) for k,v in attrs.items()]; d.attrs['encoding']='jpeg'\n",
                                         copy, d.file("huge.jpg")});
  ASSERT_EQ(made.exit_code, 0) << made.err;
  const CommandResult r = run_program({"prlimit", "--as=2000000000", haptex_binary(), "qa", copy});
  EXPECT_TRUE(r.exit_code == 1 || r.exit_code == 2) << r.exit_code << r.err;
  EXPECT_EQ(r.err.find("unexpected error"), std::string::npos) << r.err;
  EXPECT_NE((r.out + r.err).find("8192 x 8192"), std::string::npos) << r.out << r.err;
}

// Review 15, R8: a file another program holds open for writing (HDF5's lock) was called truncated or
// damaged, "copy it again". This test holds it open as an h5py session would.
TEST(BadValues, AFileAnotherProgramWritesIsNamedAsLocked) {
  const TempDir d;
  const std::string copy = copy_into(d, small_pipeline().recordings, "open elsewhere.h5");
  const hid_t held = H5Fopen(copy.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(held, 0);
  expect_refusal(run_haptex({"info", copy}), {copy, "another program has it open for writing", "HDF5_USE_FILE_LOCKING=FALSE"});
  H5Fclose(held);
  EXPECT_EQ(run_haptex({"info", copy}).exit_code, 0);
}

// Review 15, R7: a layer's unknown activation was exit 1 naming neither the file nor the layer.
TEST(BadValues, AModelLayersUnknownActivationIsNamedWhereItIs) {
  if (!python_has("h5py")) GTEST_SKIP() << "python3-h5py is not installed (make deps installs it)";
  const TempDir d;
  const std::string model = copy_into(d, quick_model(), "gelu.h5");
  const CommandResult made = run_python({"-c",
                                         "import h5py,sys\nf=h5py.File(sys.argv[1],'r+'); found=[]\n"
                                         "f.visititems(lambda n,o: found.append(o) if 'activation' in o.attrs else None)\n"
                                         "found[0].attrs['activation']='gelu'; print(found[0].name)",
                                         model});
  ASSERT_EQ(made.exit_code, 0) << made.err;
  std::string layer = made.out.substr(0, made.out.find('\n'));
  expect_refusal(run_haptex({"predict", model, "--material", small_material(), "--normal-force", "1", "--speed", "100"}),
                 {model, layer + "@activation", "'gelu' is not linear, relu or softplus", "Train the model again"});
  // The variant's own spelling was wrong in the message ("neither unified nor per_material").
  const std::string variant = copy_into(d, quick_model(), "variant.h5");
  ASSERT_EQ(run_python({"-c", "import h5py,sys\nwith h5py.File(sys.argv[1],'r+') as f: f.attrs['variant']='per_material'", variant}).exit_code, 0);
  expect_refusal(run_haptex({"predict", variant, "--material", small_material(), "--normal-force", "1", "--speed", "100"}),
                 {variant, "is 'per_material', neither unified nor per-material"});
}

// Review 5, #8: "Wo&#0;ven" in a HaTT recording became the material "Wo".
TEST(BadValues, ANulCharacterReferenceInXmlIsRefused) {
  if (!python_has("gzip")) GTEST_SKIP() << "python3 is missing";
  const TempDir d;
  const fs::path synth = fs::path(small_pipeline().recordings).parent_path() / "synth" / "recordings";
  fs::path source;
  for (const auto& e : fs::directory_iterator(synth))
    if (e.path().filename().string().find(".xml") != std::string::npos) source = e.path();
  ASSERT_FALSE(source.empty());
  const CommandResult made = run_python({"-c",
                                         "import gzip,re,sys; t=gzip.open(sys.argv[1]).read().decode();"
                                         "t=re.sub(r'<material>([^<]*)</material>', lambda m: '<material>'+m.group(1)[:2]+'&#0;'+m.group(1)[2:]+'</material>', t, 1);"
                                         "open(sys.argv[2],'w').write(t)",
                                         source.string(), d.file("nul_1.xml")});
  ASSERT_EQ(made.exit_code, 0) << made.err;
  expect_refusal(run_haptex({"convert", "hatt", d.file("nul_1.xml"), "-o", d.file("r.h5")}), {d.file("nul_1.xml"), "line ", "&#0;"});
  EXPECT_FALSE(fs::exists(d.file("r.h5")));
}

// Review 15, R9: "Café 1" and "Caf u00e9 1" make one id, caf_u00e9_1, and convert joined the two
// surfaces' recordings into one material. Names that differ only in case and punctuation still join.
TEST(BadValues, NamesThatDifferInLettersButMakeOneIdAreRefused) {
  const TempDir d;
  const auto write_pair = [&](const std::string& folder, const std::string& first, const std::string& second) {
    fs::create_directories(d.file(folder));
    test::SampleRecordingSpec spec;
    spec.seconds = 0.5;
    spec.material = first;
    test::write_text_file(d.file(folder + "/a.xml"), test::sample_recording_xml(spec));
    spec.material = second, spec.seed = 2;
    test::write_text_file(d.file(folder + "/b.xml"), test::sample_recording_xml(spec));
    return d.file(folder);
  };
  expect_refusal(run_haptex({"convert", "hatt", write_pair("two", "Caf\u00e9 1", "Caf u00e9 1"), "-o", d.file("r.h5")}),
                 {"make one material id, caf_u00e9_1, but differ in letters"});
  EXPECT_FALSE(fs::exists(d.file("r.h5")));
  const CommandResult one = run_haptex({"convert", "hatt", write_pair("one", "Woven 1", "woven-1"), "-o", d.file("w.h5")});
  EXPECT_EQ(one.exit_code, 0) << one.err;
  EXPECT_EQ(material_ids(d.file("w.h5")), std::vector<std::string>{"woven_1"});
}

// Reviews 5 and 6: a second <material> or <speed> element was skipped without a word (which one holds
// the data is not knowable), so was a second document element, and a CDATA name read as empty.
TEST(BadValues, AnXmlElementGivenTwiceIsRefusedAndCdataIsText) {
  const TempDir d;
  test::SampleRecordingSpec spec;
  spec.seconds = 0.5;
  const std::string xml = test::sample_recording_xml(spec);
  const auto write = [&](const std::string& name, const std::string& text) {
    test::write_text_file(d.file(name), text);
    return d.file(name);
  };
  const auto with = [&](const std::string& before, const std::string& after) {
    std::string text = xml;
    const std::size_t at = text.find(before);
    EXPECT_NE(at, std::string::npos) << before;
    return text.replace(at, before.size(), after);
  };
  const std::string speed = xml.substr(xml.find("<speed"), xml.find("</speed>") + 8 - xml.find("<speed"));
  const std::string two_speeds = write("speed_1.xml", with(speed, speed + "\n" + speed));
  expect_refusal(run_haptex({"convert", "hatt", two_speeds, "-o", d.file("r.h5")}), {two_speeds, "second <speed>", "line "});
  const std::string two_names = write("name_1.xml", with("<material>", "<material>Cork</material>\n<material>"));
  expect_refusal(run_haptex({"convert", "hatt", two_names, "-o", d.file("r.h5")}), {two_names, "second <material>"});
  const std::string two_documents = write("doc_1.xml", xml + "\n" + xml.substr(xml.find("<recordedData")));
  expect_refusal(run_haptex({"convert", "hatt", two_documents, "-o", d.file("r.h5")}), {two_documents, "second document element"});
  EXPECT_FALSE(fs::exists(d.file("r.h5")));

  const std::string name = spec.material;
  const std::string cdata = write("cdata_1.xml", with("<material>" + name + "</material>", "<material><![CDATA[" + name + "]]></material>"));
  const CommandResult converted = run_haptex({"convert", "hatt", cdata, "-o", d.file("r.h5")});
  ASSERT_EQ(converted.exit_code, 0) << converted.err;
  EXPECT_NE(run_haptex({"info", d.file("r.h5")}).out.find(name), std::string::npos);
}

// Review 10, F2: a <value> whose text a comment or processing instruction split was read as its first
// piece ("5<!-- -->00" stored as 5, "1<!-- -->e39" as 1, slipping past the float32 limit).
TEST(BadValues, AnXmlValueInPiecesIsReadWholeAndMarkupInsideIsRefused) {
  const TempDir d;
  test::SampleRecordingSpec spec;
  spec.seconds = 0.5;
  const std::string xml = test::sample_recording_xml(spec);
  const std::size_t first = xml.find("<value>", xml.find("<accelX")) + 7;
  const std::size_t end = xml.find("</value>", first);
  const auto write = [&](const std::string& name, const std::string& value) {
    test::write_text_file(d.file(name), std::string(xml).replace(first, end - first, value));
    return d.file(name);
  };
  for (const std::string& split : {std::string("1<!-- -->e39"), std::string("1<?pi x?>e39")}) {
    SCOPED_TRACE(split);
    const std::string file = write("split_1.xml", split);
    expect_refusal(run_haptex({"convert", "hatt", file, "-o", d.file("r.h5")}), {file, "'1e39' is beyond"});
  }
  const std::string child = write("child_1.xml", "1<b>e39</b>");
  expect_refusal(run_haptex({"convert", "hatt", child, "-o", d.file("r.h5")}), {child, "holds element <b>"});
  EXPECT_FALSE(fs::exists(d.file("r.h5")));
  const std::string joined = write("joined_1.xml", "5<!-- a note -->00");
  ASSERT_EQ(run_haptex({"convert", "hatt", joined, "-o", d.file("r.h5")}).exit_code, 0);
  const std::vector<float> accel = h5::File::open(d.file("r.h5")).root()
                                       .open_dataset("materials/" + material_ids(d.file("r.h5")).front() + "/recordings/0/accel_xyz")
                                       .read<float>();
  EXPECT_FLOAT_EQ(accel.at(0), 500.f) << "500 m/s^2, the pieces joined";
  // Review 16, F1: white space between two comments (or PIs, or CDATA sections) is dropped by the XML
  // reader, so "1<!-- --> <!-- -->5" (XML: "1 5", no number) was stored as 15, and a unit "m<!-- -->
  // <!-- -->N" read as mN divided every force by 1000.
  for (const std::string& split : {std::string("1<!-- --> <!-- -->5"), std::string("-<?a?> <?b?>1"), std::string("<![CDATA[1]]> <![CDATA[5]]>"),
                                   std::string("1<!-- --><![CDATA[5]]>")}) {
    SCOPED_TRACE(split);
    const std::string file = write("gap_1.xml", split);
    expect_refusal(run_haptex({"convert", "hatt", file, "-o", d.file("g.h5")}), {file, "side by side", "Write the text as one piece"});
  }
  const std::string unit = d.file("unit_1.xml");
  test::write_text_file(unit, std::string(xml).replace(xml.find("<ForceUnits>N</ForceUnits>"), 26, "<ForceUnits>m<!-- --> <!-- -->N</ForceUnits>"));
  expect_refusal(run_haptex({"convert", "hatt", unit, "-o", d.file("g.h5")}), {unit, "<ForceUnits>", "side by side"});
  EXPECT_FALSE(fs::exists(d.file("g.h5")));
  for (const std::string& fine : {std::string("<!-- --> <!-- -->5"), std::string("5<!-- --> <!-- -->"), std::string(" <![CDATA[5]]> ")}) {
    SCOPED_TRACE(fine);
    const std::string file = write("fine_1.xml", fine);
    EXPECT_EQ(run_haptex({"convert", "hatt", file, "-o", d.file("f.h5"), "--force"}).exit_code, 0) << "white space at either end is trimmed anyway";
  }
}

// Review 16, F8: a lone CR ends a line in XML (classic Mac line ends), but messages counted only LFs
// and named line 1 for every place.
TEST(BadValues, AnXmlFileWithCarriageReturnLineEndsIsToldByLine) {
  const TempDir d;
  test::SampleRecordingSpec spec;
  spec.seconds = 0.5;
  std::string xml = test::sample_recording_xml(spec);
  const std::size_t value = xml.find("<value>", xml.find("<accelX")) + 7;
  xml.replace(value, xml.find("</value>", value) - value, "1.2.3");
  const std::string line = std::to_string(std::count(xml.begin(), xml.begin() + std::ptrdiff_t(value), '\n') + 1);
  for (const std::string& end : {std::string("\r"), std::string("\r\n")}) {
    std::string ended;
    for (const char c : xml) ended += c == '\n' ? end : std::string(1, c);
    test::write_text_file(d.file("cr_1.xml"), ended);
    expect_refusal(run_haptex({"convert", "hatt", d.file("cr_1.xml"), "-o", d.file("r.h5")}), {"line " + line + " ", "'1.2.3'"});
  }
}

// Review 7: a CSV column named twice was read from its first copy without a word (Python's
// csv.DictReader keeps the last), a blank line between rows was passed over, and 1e-40 was stored
// with its digits lost.
TEST(BadValues, ACsvRecordingWithAColumnTwiceABlankRowOrASubnormalIsRefused) {
  const TempDir d;
  test::SampleRecordingSpec spec;
  spec.seconds = 0.5;
  const std::string csv = test::sample_recording_csv(spec);
  const std::size_t header_end = csv.find('\n'), second_row = csv.find('\n', header_end + 1) + 1;
  const std::string header = csv.substr(0, header_end);
  const std::string first_column = header.substr(0, header.find(','));
  const auto write = [&](const std::string& name, const std::string& text) {
    test::write_text_file(d.file(name), text);
    return d.file(name);
  };
  // The header's first column once more at its end, and a value for it in every row.
  std::string twice;
  std::istringstream rows(csv);
  for (std::string line; std::getline(rows, line);) twice += line + "," + (twice.empty() ? first_column : "0") + "\n";
  const std::string column_twice = write("twice_1.csv", twice);
  expect_refusal(run_haptex({"convert", "hatt", column_twice, "-o", d.file("r.h5")}),
                 {column_twice, "line 1, column '" + first_column + "'", "twice"});
  const std::string blank = write("blank_1.csv", csv.substr(0, second_row) + "\n" + csv.substr(second_row));
  expect_refusal(run_haptex({"convert", "hatt", blank, "-o", d.file("r.h5")}), {blank, "line 3", "blank"});
  std::string tiny_text = csv;
  const std::size_t cell = tiny_text.find(',', second_row) + 1;
  tiny_text.replace(cell, tiny_text.find(',', cell) - cell, "1e-40");
  const std::string tiny = write("tiny_1.csv", tiny_text);
  expect_refusal(run_haptex({"convert", "hatt", tiny, "-o", d.file("r.h5")}), {tiny, "line 3", "under 1.2e-38"});
  EXPECT_FALSE(fs::exists(d.file("r.h5")));
  const std::string trailing = write("end_1.csv", csv + "\n\n");  // blank lines at the end are no row
  EXPECT_EQ(run_haptex({"convert", "hatt", trailing, "-o", d.file("r.h5")}).exit_code, 0);
}

// Material `from` of a dataset named `name` instead, under the id the name gives (its group and its
// entry in /windows/materials).
void rename_material(const std::string& dataset, const std::string& from, const std::string& name) {
  const std::string id = material_id(name);
  Edit e(dataset);
  e.copy("materials/" + from, "materials/" + id);
  e.remove("materials/" + from);
  e.group("materials/" + id).set_attr("name", name);
  std::vector<std::string> ids = e.dataset("windows/materials").read_strings();
  std::replace(ids.begin(), ids.end(), from, id);
  e.remove("windows/materials");
  e.group("windows").write_strings("materials", ids);
}

// Review 22, F3: the lower bound was checked on the text's number, before the unit: 5e-36 mN was stored
// as the subnormal 5e-39 N. It is refused after the unit, as the upper bound is.
TEST(BadValues, AValueThatItsUnitMakesSubnormalIsRefused) {
  const TempDir d;
  const fs::path xml = one_synth_recording(d.file("s"));
  std::string text = read_recording_text(xml.string());
  text.replace(text.find("<ForceUnits>N</ForceUnits>"), 26, "<ForceUnits>mN</ForceUnits>");
  const std::size_t force = text.find("<value>", text.find("<forceNormal")) + 7;
  text.replace(force, text.find("</value>", force) - force, "5e-36");
  write_recording_text(xml.string(), text);
  expect_refusal(run_haptex({"convert", "hatt", xml.string(), "-o", d.file("r.h5")}), {xml.string(), "force", "sample 1", "under 1.2e-38"});
  EXPECT_FALSE(fs::exists(d.file("r.h5")));
}

// Review 4, #7: evaluate wrote a material name's ESC and BEL into report.md and every CSV, so `cat
// report.md` retitled and cleared the terminal.
TEST(BadValues, AReportHoldsNoTerminalEscapeFromAName) {
  const TempDir d;
  const std::string dataset = d.file("d.h5");
  fs::copy_file(small_pipeline().dataset, dataset);
  // The material takes the hostile name's own id, as extract or convert would give it (qa's layout.required).
  const std::string hostile = "Wov\x1b]0;pwned\x07en\x1b[2J\u202e\t\nx<script>alert(1)</script>";
  rename_material(dataset, material_ids(dataset).front(), hostile);
  ASSERT_EQ(run_haptex({"split", dataset, "-o", d.file("s.json"), "--no-plots", "-q"}).exit_code, 0);
  ASSERT_EQ(run_haptex(quick_train_args(dataset, d.file("s.json"), d.file("m.h5"))).exit_code, 0);
  const CommandResult r = run_haptex({"evaluate", dataset, "--split", d.file("s.json"), "--model", d.file("m.h5"), "-o", d.file("rep"),
                                      "--repeats", "2", "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  int files = 0;
  for (const auto& entry : fs::directory_iterator(d.file("rep"))) {
    const std::string name = entry.path().filename().string();
    if (entry.path().extension() != ".md" && entry.path().extension() != ".csv" && entry.path().extension() != ".html") continue;
    ++files;
    const std::string text = file_bytes(entry.path().string());
    EXPECT_EQ(text.find_first_of("\x1b\x07"), std::string::npos) << name;
    EXPECT_EQ(text.find("\u202e"), std::string::npos) << name;
    EXPECT_EQ(text.find("\t\nx"), std::string::npos) << name << ": a line splits where the name does";
  }
  EXPECT_GE(files, 3);
  EXPECT_NE(file_bytes(d.file("rep/report.md")).find("Wov\\\\x1b"), std::string::npos) << "the name, escaped and markdown-escaped";
  // report.html: the name is text, in its tables and its listening section alike; the page's one script is its own.
  const std::string html = file_bytes(d.file("rep/report.html"));
  EXPECT_EQ(html.find("<script>alert"), std::string::npos);
  EXPECT_EQ(html.find("<script>"), html.rfind("<script>"));
  EXPECT_NE(html.find("<h3>Wov\\x1b]0;pwned"), std::string::npos);
  EXPECT_NE(html.find("\\x1b[2J\\u202e\\x09\\x0ax&lt;script&gt;alert(1)&lt;/script&gt; (<code>"), std::string::npos);
  // haptex view's page alike.
  ASSERT_EQ(run_haptex({"view", dataset, "--split", d.file("s.json"), "-o", d.file("site"), "-q"}).exit_code, 0);
  const std::string site = file_bytes(d.file("site/index.html"));
  EXPECT_EQ(site.find("<script>alert"), std::string::npos);
  EXPECT_EQ(site.find("<script>"), site.rfind("<script>"));
  EXPECT_EQ(site.find_first_of("\x1b\x07"), std::string::npos);
  EXPECT_NE(site.find("\\x1b[2J\\u202e\\x09\\x0ax&lt;script&gt;alert(1)&lt;/script&gt; (<code>"), std::string::npos);
}

// Whatever a command prints, a name's control characters are escaped (apps/printable_stream.hpp), and
// a NUL quoted from an input does not cut the message short.
TEST(BadValues, NoCommandPrintsATerminalEscapeOrStopsAtANul) {
  const TempDir d;
  const CommandResult r = run_haptex({"capture", "record", "--device", "fake:size=160x120,lockstep", "--material", "felt\x1b]0;pwned\x07",
                                      "--presses", "1", "-o", d.file("s")});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.find('\x1b'), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("felt\\x1b]0;pwned\\x07"), std::string::npos) << r.out;
  std::ofstream(d.file("nul.csv"), std::ios::binary) << std::string("force,speed\n1,1\0" "00\n", 19);
  expect_refusal(run_haptex({"predict", quick_model(), "--material", small_material(), "--csv", d.file("nul.csv")}),
                 {"line 2", "\\x00", "Fix or remove the line"});
}

// Review 2, #8: a newline or tab inside a name is the name's, not the line's: success lines and
// errors show it escaped like any control character, so a line never splits where the name does.
TEST(BadValues, ANewlineOrTabInANameIsPrintedEscaped) {
  const SmallPipeline& p = small_pipeline();
  const TempDir d;
  {
    std::ofstream trajectory(d.file("traj.csv"));
    trajectory << "force,speed\n";
    for (int i = 0; i < 3000; ++i) trajectory << "1,100\n";
  }
  const std::string name = "a\n\tb";
  const std::vector<std::vector<std::string>> runs = {
      {"merge", p.gelsight, "-o", d.file(name + ".h5")},
      {"align", "--recordings", p.recordings, "--gelsight", p.gelsight, "-o", d.file(name + ".d.h5")},
      {"split", p.dataset, "-o", d.file(name + ".json")},
      {"windows", p.dataset, "--split", p.split, "-o", d.file(name + ".w.h5")},
      {"render", quick_model(), "--material", small_material(), "--trajectory", d.file("traj.csv"), "-o", d.file(name + ".wav"),
       "--csv", d.file(name + ".csv")},
  };
  for (const auto& args : runs) {
    SCOPED_TRACE(args.front());
    const CommandResult r = run_haptex(args);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ((r.out + r.err).find("a\n"), std::string::npos) << r.out << r.err;
    EXPECT_NE(r.out.find("a\\x0a\\x09b"), std::string::npos) << r.out;
  }
  // Review 6: the WAV's comment (naming the trajectory) kept them raw; sox --i and mediainfo print it.
  fs::copy_file(d.file("traj.csv"), d.file(name + ".csv.traj"));
  ASSERT_EQ(run_haptex({"render", quick_model(), "--material", small_material(), "--trajectory", d.file(name + ".csv.traj"), "-o", d.file("t.wav")})
                .exit_code, 0);
  const std::string comment = read_wav_file(d.file("t.wav")).comment;
  EXPECT_EQ(comment.find("a\n"), std::string::npos) << comment;
  EXPECT_NE(comment.find("a\\x0a\\x09b"), std::string::npos) << comment;
  const CommandResult missing = run_haptex({"qa", d.file("no\nsuch.h5")});
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("no\\x0asuch.h5"), std::string::npos) << missing.err;
}

// A recordings file whose accel is float64 holding 1e39 (beyond float32, which the layout says) is
// refused by align naming the dataset, instead of becoming NaN windows.
TEST(BadValues, AlignRefusesASignalOfTheWrongType) {
  const SmallPipeline& p = small_pipeline();
  const TempDir d;
  const std::string recordings = d.file("r.h5");
  fs::copy_file(p.recordings, recordings);
  const std::string accel = "materials/" + material_ids(recordings).front() + "/recordings/0/accel";
  {
    Edit edit(recordings);
    std::vector<double> values(20000, 0.5);
    values[7] = 1e39;
    edit.replace<double>(accel, values, {values.size()});
  }
  expect_refusal(run_haptex({"align", "--recordings", recordings, "--gelsight", p.gelsight, "-o", d.file("d.h5")}),
                 {recordings, "/accel", "float64, expected float32"});
  EXPECT_FALSE(fs::exists(d.file("d.h5")));
}

}  // namespace
}  // namespace haptex::test
