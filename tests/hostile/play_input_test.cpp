// Issue 34 meets issue 32's promises: haptex play's stream, device and recording outputs. A bad line is
// refused naming standard input and the line, exit 2; a recording never replaces what haptex did not
// write, nor an input, and is refused before anything plays.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include "tests/hostile/hostile_support.hpp"
#include "tests/support/fake_sound_card.hpp"
#include "tests/support/quick_models.hpp"
#include "tests/support/small_pipeline.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {
namespace fs = std::filesystem;

std::vector<std::string> play(const std::vector<std::string>& more) {
  std::vector<std::string> args = {"play", quick_model(false), "--material", small_material(), "--device", "capture"};
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

std::string stroke(const TempDir& d) {
  std::ofstream csv(d.file("stroke.csv"));
  csv << "force,speed\n";
  for (int i = 0; i < 3000; ++i) csv << "1.5,100\n";
  return d.file("stroke.csv");
}

TEST(HostilePlay, BadLinesOnStandardInputAreRefusedWithTheirLine) {
  const FakeSoundCard card;
  const TempDir d;
  const std::vector<std::pair<std::string, std::string>> streams = {
      {"1 2\n1 2 3 4\n", "line 2: holds 4 fields"},
      {"t,force,speed\n0,1,2\n0.001,-1,2\n", "line 3: negative force or speed"},
      {"1 1e39\n", "line 1: '1e39' is beyond"},
      {"1 inf\n", "line 1: 'inf' is not a finite number"},
      {"1 \xff\xfe\n", "line 1: '\\xff\\xfe' is not a number"},
      {"1 2\n\n3 x\n", "line 3: 'x' is not a number"},
      {std::string(5000, '1'), "line 1: is longer than 4096 bytes"},
      {"1\n", "line 1: holds 1 field."},
      // Review 11, C1: an empty field between commas was skipped; a first line of junk was a header.
      {"1,,50\n", "line 1: '' is not a number"},
      {"\x01\x02 \x03\n1 50\n", "line 1: '\\x01\\x02' is not a number"},
      {"force speed\n", "ended before its first action"},
      {"", "ended before its first action"}};
  for (const auto& [input, message] : streams) {
    SCOPED_TRACE(message);
    { std::ofstream(d.file("in.txt"), std::ios::binary) << input; }
    expect_refusal(run_haptex_fed(play({"--actions", "-"}), d.file("in.txt")), {"standard input: " + message});
  }
}

// The first line that is not blank may name the columns.
TEST(HostilePlay, AHeaderAfterBlankLinesIsAHeader) {
  const FakeSoundCard card;
  const TempDir d;
  std::ofstream(d.file("in.txt")) << "\n \nforce speed\n1 50\n";
  const CommandResult r = run_haptex_fed(play({"--actions", "-"}), d.file("in.txt"));
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

TEST(HostilePlay, ActionsComeOnlyFromStandardInput) {
  const FakeSoundCard card;
  const TempDir d;
  expect_refusal(run_haptex(play({"--actions", stroke(d)})), {stroke(d), "--actions reads standard input only", "--trajectory"});
  expect_refusal(run_haptex(play({})), {"give --trajectory FILE, or --actions -"});
}

TEST(HostilePlay, ARecordingNeverReplacesWhatHaptexDidNotWriteNorAnInput) {
  const FakeSoundCard card;
  const TempDir d;
  const std::string trajectory = stroke(d);
  std::ofstream(d.file("mine.wav")) << "my own recording";
  std::ofstream(d.file("take.csv")) << "my notes";
  for (const bool force : {false, true}) {
    SCOPED_TRACE(force ? "--force" : "");
    std::vector<std::string> extra = force ? std::vector<std::string>{"--force"} : std::vector<std::string>{};
    auto with = [&](std::vector<std::string> args) {
      args.insert(args.end(), extra.begin(), extra.end());
      return play(args);
    };
    expect_refusal(run_haptex(with({"--trajectory", trajectory, "--record", d.file("mine.wav")})), {d.file("mine.wav")});
    expect_refusal(run_haptex(with({"--trajectory", trajectory, "--record", d.file("take.wav")})), {d.file("take.csv")});
    expect_refusal(run_haptex(with({"--trajectory", trajectory, "--record", d.file("stroke.wav")})), {trajectory, "also an input"});
    expect_refusal(run_haptex(with({"--trajectory", trajectory, "--record", d.file("no/such/folder/r.wav")})), {"does not exist"});
    EXPECT_FALSE(fs::exists(card.raw())) << "refused before anything played";
  }
  EXPECT_EQ(file_bytes(d.file("mine.wav")), "my own recording");
  EXPECT_EQ(file_bytes(d.file("take.csv")), "my notes");
  EXPECT_FALSE(fs::exists(d.file("take.wav")));
  // Its own recording it replaces with --force, both files together.
  ASSERT_EQ(run_haptex(play({"--trajectory", trajectory, "--record", d.file("r.wav")})).exit_code, 0);
  expect_refusal(run_haptex(play({"--trajectory", trajectory, "--record", d.file("r.wav")})), {d.file("r.wav"), "--force"});
  EXPECT_EQ(run_haptex(play({"--trajectory", trajectory, "--record", d.file("r.wav"), "--force"})).exit_code, 0);
  EXPECT_EQ(partial_files(d.path().string()), std::vector<std::string>{});
  // Review 14, F5: the actions played back from the CSV a recording wrote, on standard input, into the
  // same recording: that CSV is an input, and --force does not replace it.
  const std::string kept = file_bytes(d.file("r.csv"));
  expect_refusal(run_haptex_fed(play({"--actions", "-", "--record", d.file("r.wav"), "--force"}), d.file("r.csv")),
                 {d.file("r.csv"), "also an input of the command (standard input)"});
  EXPECT_EQ(file_bytes(d.file("r.csv")), kept);
}

// Review 12, F3: an ALSA device string is a configuration language. With the system's configuration,
// `file:FILE=X` truncates X (the model being read, in the review) and `file:FILE=|cmd` runs cmd
// through a shell. --device takes a device's name only.
TEST(HostilePlay, TheDeviceIsANameNeverAFileOrACommand) {
  const TempDir d;
  const std::string trajectory = stroke(d);
  fs::copy_file(quick_model(false), d.file("model.h5"));
  std::ofstream(d.file("victim")) << "a user's file";
  const std::string mine = file_bytes(d.file("model.h5"));
  const std::vector<std::string> devices = {"file:FILE=" + d.file("model.h5") + ",FORMAT=raw", "file:FILE=victim,FORMAT=raw",
                                            "file:FILE=|touch " + d.file("ran") + ",FORMAT=raw", "file:FILE=|touch,FORMAT=raw",
                                            "tee:default,victim", "{type file file victim}", "plug:'file:FILE=victim'", "default;x", "",
                                            // Review 13, F3: the file plugin as another plugin's slave.
                                            "plug:SLAVE=file:victim", "plug:file:victim", "plug:SLAVE=FILE:victim", "dmix:tee:default,victim"};
  for (const std::string& device : devices) {
    SCOPED_TRACE(device);
    const CommandResult r = run_haptex_in(d.path(), {"play", d.file("model.h5"), "--material", small_material(), "--trajectory", trajectory,
                                                     "--device", device});
    expect_refusal(r, {"--device"});
  }
  EXPECT_EQ(file_bytes(d.file("model.h5")), mine) << "the model it reads is untouched";
  EXPECT_EQ(file_bytes(d.file("victim")), "a user's file");
  EXPECT_FALSE(fs::exists(d.file("ran"))) << "no command ran";
  EXPECT_FALSE(fs::exists(d.file("touch")));
}

// Review 12, F2: a second run recording to the same name was played to its end and then lost its
// recording. The names are taken before anything plays, so it is refused at once.
TEST(HostilePlay, TwoRunsRecordingToOneNameRefuseEachOtherAtTheStart) {
  const FakeSoundCard card;
  const TempDir d;
  {
    std::ofstream csv(d.file("long.csv"));
    csv << "force,speed\n";
    for (int i = 0; i < 40000; ++i) csv << "1.5,100\n";  // 4 s
  }
  CommandResult first;
  std::thread a([&] { first = run_haptex(play({"--trajectory", d.file("long.csv"), "--record", d.file("r.wav")})); });
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  const auto start = std::chrono::steady_clock::now();
  const CommandResult second = run_haptex(play({"--trajectory", d.file("long.csv"), "--record", d.file("r.wav")}));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  a.join();
  expect_refusal(second, {d.file("r.wav"), "another haptex run"});
  EXPECT_LT(seconds, 2.0) << "refused before it played, not after its 4 s";
  EXPECT_EQ(first.exit_code, 0) << first.err;
  EXPECT_TRUE(fs::exists(d.file("r.wav")) && fs::exists(d.file("r.csv")));
}

}  // namespace
}  // namespace haptex::test
