// Issue 32, classes 8, 9 and 17: what the command line itself may carry. One rule for names and paths
// (valid UTF-8, the first bad byte named, before any work); an output named "" refused before any work;
// fault percentages and frame counts within their range.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "tests/hostile/hostile_support.hpp"
#include "tests/support/quick_models.hpp"
#include "tests/support/small_pipeline.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {
namespace fs = std::filesystem;

const std::string kLatin1 = "caf\xe9";  // "café" in Latin-1: byte 3 is no UTF-8

TEST(CommandLine, APathThatIsNotUtf8IsRefusedBeforeAnyWork) {
  const SmallPipeline& p = small_pipeline();
  const TempDir d;
  const std::string dataset = d.file(kLatin1 + ".h5");
  fs::copy_file(p.dataset, dataset);
  const std::vector<std::vector<std::string>> commands = {
      {"split", dataset, "-o", d.file("s.json")},
      {"split", p.dataset, "-o", d.file(kLatin1 + ".json")},
      {"train", dataset, "--split", p.split, "-o", d.file("m.h5")},
      {"align", "--recordings", p.recordings, "--gelsight", p.gelsight, "-o", d.file(kLatin1 + "_aligned.h5")},
      {"evaluate", dataset, "--split", p.split, "--model", quick_model(), "-o", d.file("rep")},
  };
  for (const auto& args : commands) {
    SCOPED_TRACE(args.front());
    expect_refusal(run_haptex(args), {"not valid UTF-8", "byte", "caf\\xe9"});
    EXPECT_EQ(partial_files(d.path().string()), std::vector<std::string>{});
  }
  EXPECT_EQ(files_named(d.path().string(), {"s.json", "m.h5", kLatin1 + ".json", kLatin1 + "_aligned.h5", "rep"}),
            std::vector<std::string>{});
}

TEST(CommandLine, AFileNameThatIsNotUtf8InAFolderIsRefused) {
  const TempDir d;
  fs::create_directory(d.file("recordings"));
  fs::copy_file(*fs::directory_iterator(fs::path(small_pipeline().recordings).parent_path() / "synth" / "recordings"),
                d.file("recordings/" + kLatin1 + "_0.xml.gz"));
  expect_refusal(run_haptex({"convert", "hatt", d.file("recordings"), "-o", d.file("r.h5")}), {"not valid UTF-8", "byte"});
  EXPECT_FALSE(fs::exists(d.file("r.h5")));
}

TEST(CommandLine, AnEmptyOutputNameIsRefusedBeforeAnyWork) {
  const SmallPipeline& p = small_pipeline();
  const TempDir d;
  std::ofstream(d.file("traj.csv")) << "force,speed\n1,100\n";
  const std::vector<std::vector<std::string>> commands = {
      {"convert", "hatt", (fs::path(p.recordings).parent_path() / "synth" / "recordings").string(), "-o", ""},
      {"align", "--recordings", p.recordings, "--gelsight", p.gelsight, "-o", ""},
      {"merge", p.gelsight, "-o", ""},
      {"train", p.dataset, "--split", p.split, "-o", ""},
      {"train", p.dataset, "--split", p.split, "-o", d.file("m.h5"), "--log", ""},
      {"windows", p.dataset, "--split", p.split, "-o", ""},
      {"render", quick_model(), "--material", small_material(), "--trajectory", d.file("traj.csv"), "-o", ""},
      {"split", p.dataset, "-o", ""},
  };
  for (const auto& args : commands) {
    SCOPED_TRACE(args.front());
    const auto start = std::chrono::steady_clock::now();
    expect_refusal(run_haptex(args), {"is empty, which names no file"});
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5)) << "refused before the work";
  }
  EXPECT_FALSE(fs::exists(d.file("m.h5")));
  // An empty value of any option is refused, not taken as no option (issue 32, review 2).
  expect_refusal(run_haptex({"align", "--recordings", p.recordings, "--gelsight", p.gelsight, "--names", "", "-o", d.file("a.h5")}),
                 {"--names", "is empty"});
}

TEST(CommandLine, FaultPercentagesAndFrameCountsStayInRange) {
  const TempDir d;
  expect_refusal(run_haptex({"capture", "record", "--device", "fake:lockstep,drop=101", "--material", "Cork", "-o", d.file("s")}),
                 {"drop", "percentage from 0 to 100"});
  expect_refusal(run_haptex({"capture", "record", "--device", "fake:lockstep", "--material", "Cork", "--pre-frames", "2000000000",
                             "-o", d.file("s")}),
                 {"--pre-frames", "at most 1000"});
  EXPECT_FALSE(fs::exists(d.file("s")));
}

// CLI11 read 025 as octal, 0x10 as hexadecimal and " 30" as 30, and wrapped -1 into 2^64-1: every
// number on the command line is plain decimal (issue 32, review 2). Refused before any work.
TEST(CommandLine, NumbersAreReadAsPlainDecimals) {
  const SmallPipeline& p = small_pipeline();
  const TempDir d;
  expect_refusal(run_haptex({"split", p.dataset, "-o", d.file("s.json"), "--sections", "025"}), {"--sections", "'025'", "decimal"});
  expect_refusal(run_haptex({"split", p.dataset, "-o", d.file("s.json"), "--seed", "-1"}), {"--seed", "not -1", "from 0 to"});
  expect_refusal(run_haptex({"train", p.dataset, "--split", p.split, "-o", d.file("m.h5"), "--epochs", "0x1"}), {"--epochs", "'0x1'"});
  expect_refusal(run_haptex({"capture", "record", "--device", "fake:lockstep", "--material", "Cork", "--fps", " 30", "-o", d.file("r")}),
                 {"--fps", "' 30'"});
  expect_refusal(run_haptex({"capture", "record", "--device", "fake:lockstep", "--material", "Cork", "--seconds", "0x1", "-o", d.file("r")}),
                 {"--seconds", "'0x1'"});
  // Review 6: a device spec's drop=025 was 25 %, --size 0160x120 was 160x120, --fps 0 passed silently,
  // and --presses 2147483648 got CLI11's "Could not convert" alone.
  for (const std::string device : {"fake:size=160x120,drop=025,lockstep", "fake:size=0160x120,lockstep"})
    expect_refusal(run_haptex({"capture", "record", "--device", device, "--material", "Cork", "-o", d.file("r")}), {"'0", "in plain decimals"});
  expect_refusal(run_haptex({"capture", "record", "--device", "fake:lockstep", "--material", "Cork", "--size", "0160x120", "-o", d.file("r")}),
                 {"--size 0160x120", "expected WIDTHxHEIGHT"});
  expect_refusal(run_haptex({"capture", "record", "--device", "fake:lockstep", "--material", "Cork", "--fps", "0", "-o", d.file("r")}),
                 {"--fps", "must be above 0"});
  expect_refusal(run_haptex({"capture", "record", "--device", "fake:lockstep", "--material", "Cork", "--presses", "2147483648", "-o", d.file("r")}),
                 {"--presses", "a whole number up to 2147483647"});
  EXPECT_EQ(run_haptex({"split", p.dataset, "-o", d.file("s.json"), "--sections", "25", "--seed", "0", "--no-plots"}).exit_code, 0)
      << "plain decimals still work";
  // A material name with no letter or digit makes no material id: refused before a press is taken.
  expect_refusal(run_haptex({"capture", "record", "--device", "fake:size=160x120,lockstep", "--material", "\u2014 !", "-o", d.file("r")}),
                 {"--material", "no letter or digit"});
  EXPECT_FALSE(fs::exists(d.file("r")));
  // Review 12, C2: an option with a range (min-coverage, 0 to 1) gave CLI11's "not in range" for 0x10
  // and an example outside its range; the plain-decimal rule speaks first, with the option's default.
  for (const std::string value : {"0x10", " 0.5", "5,5", "1_000", "0.5 "})
    expect_refusal(run_haptex({"split", p.dataset, "-o", d.file("s.json"), "--min-coverage", value}),
                   {"--min-coverage", "'" + value + "' is not a plain decimal", "e.g. --min-coverage 0.9"});
  // Review 14, F11: a frame size is digits only, in synth, capture record and the fake device alike.
  for (const std::string size : {"0960x720", "+960x720", " 960x720", "960x+720", "960x0720", "960X720", "960x720 "})
    expect_refusal(run_haptex({"synth", "materials", "-n", "1", "--size", size, "-o", d.file("syn")}), {"--size", "WIDTHxHEIGHT"});
  expect_refusal(run_haptex({"capture", "record", "--device", "fake:lockstep", "--material", "Cork", "--size", "+160x120", "-o", d.file("r")}),
                 {"--size +160x120", "expected WIDTHxHEIGHT"});
  expect_refusal(run_haptex({"capture", "record", "--device", "fake:size=+160x120,lockstep", "--material", "Cork", "-o", d.file("r")}),
                 {"'+160x120'", "in plain decimals"});
  EXPECT_FALSE(fs::exists(d.file("syn")));
  // Grey levels end at 255: a larger --pixel-threshold would find no press and blame the footage.
  expect_refusal(run_haptex({"capture", "extract", p.gelsight, "--pixel-threshold", "1000", "-o", d.file("g.h5")}), {"--pixel-threshold", "1000"});
}

// Issue 32, class 17 (second review): a value is all of its text, in decimal, within its range, once.
TEST(CommandLine, CaptureValuesAreReadWholeAndOnce) {
  const TempDir d;
  const auto record = [&](std::vector<std::string> extra) {
    std::vector<std::string> args{"capture", "record", "--device", "fake:size=160x120,lockstep", "--material", "Cork", "-o", d.file("s")};
    args.insert(args.end(), extra.begin(), extra.end());
    return run_haptex(args);
  };
  expect_refusal(record({"--control", "gain=1e39"}), {"--control gain=1e39", "whole decimal number"});
  expect_refusal(record({"--control", "gain=0x10"}), {"--control gain=0x10", "whole decimal number"});
  expect_refusal(record({"--control", "gain=3", "--control", "gain=4"}), {"--control gain=4", "given twice"});
  expect_refusal(record({"--size", "160x120x3"}), {"--size 160x120x3", "WIDTHxHEIGHT"});
  expect_refusal(record({"--seconds", "1e39"}), {"--seconds", "at most 3.4e38 in size"});
  expect_refusal(record({"--seconds", "2e6"}), {"--seconds", "at most 1e6"});
  // Review 2, #15: a --sensors list (even a FIFO) was ignored unread when --device named the camera.
  expect_refusal(record({"--sensors", d.file("sensors.json")}), {"--sensors requires --serial"});
  const auto device = [&](const std::string& spec) {
    return run_haptex({"capture", "record", "--device", spec, "--material", "Cork", "-o", d.file("s")});
  };
  expect_refusal(device("fake:lockstep,fps=0x1e"), {"fps", "'0x1e' is not a number"});
  expect_refusal(device("fake:lockstep,fps=30,fps=40"), {"fps", "given twice"});
  // Review 8: whole-number keys took fractions and exponents and cut them (disconnect=1.5 was 1 frame).
  for (const std::string spec : {"fake:lockstep,disconnect=1.5", "fake:lockstep,seed=0.5", "fake:lockstep,seed=1e3",
                                 "fake:lockstep,presses=2.5", "fake:lockstep,stall=10:1.5"}) {
    SCOPED_TRACE(spec);
    expect_refusal(device(spec), {"is not a whole number"});
  }
  expect_refusal(device("fake:lockstep,size=320.5x240"), {"'320.5x240' is not WIDTHxHEIGHT in plain decimals"});
  expect_refusal(device("fake:lockstep=1"), {"lockstep", "takes no value"});
  EXPECT_FALSE(fs::exists(d.file("s")));
}

// Review 3: errors of a command's part were prefixed by the command alone ("haptex capture:").
TEST(CommandLine, AnErrorNamesThePartOfTheCommandThatRan) {
  const TempDir d;
  const CommandResult r = run_haptex({"capture", "extract", d.file("nowhere"), "-o", d.file("g.h5")});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err.rfind("haptex capture extract: error: ", 0), 0u) << r.err;
}

// An unknown flag was hidden behind a missing argument: `haptex --bogus train` said "dataset is
// required", which sends the user after the wrong mistake. A negative number is a value, not a flag.
TEST(CommandLine, AnUnknownFlagIsNamedBeforeAMissingArgument) {
  for (const std::vector<std::string>& args : {std::vector<std::string>{"--bogus", "train"}, {"train", "--bogus"}, {"train", "--bogus=3"}}) {
    const CommandResult r = run_haptex(args);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("is no option of 'haptex train'"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("'--bogus"), std::string::npos) << r.err;
  }
  const CommandResult known = run_haptex({"train", "-v"});
  EXPECT_NE(known.err.find("dataset is required"), std::string::npos) << known.err;
  const CommandResult value = run_haptex({"train", "--split", "-3"});
  EXPECT_EQ(value.err.find("no option"), std::string::npos) << value.err;
}

// Review 15, R14: an option whose value was left out took the next flag as it: `-o --force` wrote a
// file named --force, without --force applied. R13: qa printed a newline inside an object's name raw.
TEST(CommandLine, AFlagIsNoOptionsValueAndQaKeepsANameOnItsLine) {
  const TempDir d;
  for (const std::string flag : {"--force", "--json", "-q"}) {
    const CommandResult r = run_program({haptex_binary(), "split", small_pipeline().dataset, "--no-plots", "-o", flag}, d.path().string());
    expect_refusal(r, {"-o", "is followed by '" + flag + "', which is an option, not its value"});
    EXPECT_FALSE(fs::exists(d.file(flag)));
  }
  const std::string copy = copy_into(d, small_pipeline().dataset, "named.h5");
  ASSERT_EQ(run_python({"-c", "import h5py,sys\nwith h5py.File(sys.argv[1],'r+') as f: f['materials/x\\ny\\tz'] = [1.0]", copy}).exit_code, 0);
  const CommandResult qa = run_haptex({"qa", copy});
  EXPECT_NE(qa.out.find("x\\x0ay\\x09z"), std::string::npos) << qa.out;
  EXPECT_EQ(qa.out.find("x\ny"), std::string::npos) << "the line splits where the name does";
}

// Review 15, R1: the model of predict, render and play (and their images, trajectories, evaluate's
// --truth) went through CLI11's ExistingFile, which answered in its own words, without the fix, and
// with "file": null in --json. They are checked as every other input is.
TEST(CommandLine, AMissingModelIsNamedAsEveryOtherInputIs) {
  const TempDir d;
  std::filesystem::create_symlink(d.file("nowhere"), d.file("dangling.h5"));
  std::filesystem::create_directory(d.file("folder.h5"));
  const std::vector<std::pair<std::string, std::string>> models = {
      {d.file("none.h5"), "no such file"}, {d.file("dangling.h5"), "symbolic link to a file that does not exist"}, {d.file("folder.h5"), "is a folder"}};
  for (const auto& [model, why] : models) {
    for (const std::vector<std::string>& args : {std::vector<std::string>{"--json", "predict", model, "--material", "x", "--normal-force", "1", "--speed", "1"},
                                                 {"--json", "render", model, "--material", "x", "--trajectory", d.file("t.csv"), "-o", d.file("o.wav")},
                                                 {"--json", "play", model, "--material", "x", "--trajectory", d.file("t.csv")}}) {
      const CommandResult r = run_haptex(args);
      expect_refusal(r, {model, why});
      const nlohmann::json error = nlohmann::json::parse(r.out, nullptr, false);
      ASSERT_TRUE(error.is_object()) << r.out;
      EXPECT_EQ(error["error"]["file"], model) << r.out;
      EXPECT_FALSE(error["error"]["fix"].is_null()) << r.out;
    }
  }
  EXPECT_FALSE(std::filesystem::exists(d.file("o.wav")));
}

}  // namespace
}  // namespace haptex::test
