// haptex play as a user runs it, without a sound card: an ALSA configuration of the test's own (ALSA's
// file plugin over its null plugin) takes the samples as a card would, into a raw file. What it
// captures must be what `haptex render --live` renders for the same actions, method and seed,
// resampled as the player resamples (issue 34), and a live stream on standard input at 1 kHz must
// play without an underrun.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "core/json/schema.hpp"
#include "core/signal/resample.hpp"
#include "tests/support/fake_sound_card.hpp"
#include "tests/support/quick_models.hpp"
#include "tests/support/run_haptex.hpp"
#include "tests/support/small_pipeline.hpp"
#include "tests/support/sound_server.hpp"
#include "tests/support/temp_dir.hpp"
#include "tests/support/wav_file.hpp"

extern char** environ;

namespace haptex::test {
namespace {
namespace fs = std::filesystem;

std::string material() { return json::read_file(small_pipeline().split)["materials"][0]["id"]; }

std::vector<std::string> play_args(const std::vector<std::string>& more) {
  std::vector<std::string> args = {"--json", "play", quick_model(false), "--material", material(), "--device", "capture", "--full-scale", "20"};
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

// 1.2 s of a stroke at 10 kHz.
std::string write_stroke(const TempDir& dir) {
  std::ofstream csv(dir.file("stroke.csv"));
  csv << "time_s,force,speed\n";
  for (int i = 0; i < 12000; ++i)
    csv << i * 1e-4 << "," << 1.5 + 0.8 * std::sin(1.9 * i * 1e-4) << "," << 140 + 100 * std::sin(4.4 * i * 1e-4) << "\n";
  return dir.file("stroke.csv");
}

// The render CSV's acceleration column.
std::vector<double> acceleration(const std::string& csv) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  std::vector<double> out;
  while (std::getline(in, line)) out.push_back(std::stod(line.substr(line.rfind(',') + 1)));
  return out;
}

// What render --live gives for the trajectory, from its first sample played on, at 48 kHz in 16 bits.
std::vector<std::int16_t> rendered_as_played(const TempDir& dir, const std::string& trajectory, const std::vector<std::string>& method) {
  std::vector<std::string> args = {"--json", "render", quick_model(false), "--material", material(), "--trajectory", trajectory,
                                   "-o", dir.file("r.wav"), "--csv", dir.file("r.csv"), "--live", "--force"};
  args.insert(args.end(), method.begin(), method.end());
  const CommandResult r = run_haptex(args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const std::size_t first = nlohmann::json::parse(r.out)["first_frame_sample"];
  const std::vector<double> signal = acceleration(dir.file("r.csv"));
  signal::StreamResampler resample(48000, 10000);
  std::vector<double> y;
  resample.push(std::span(signal).subspan(first), y);
  std::vector<std::int16_t> out;
  for (const double a : y) out.push_back(std::int16_t(std::lrint(std::clamp(a / 20, -1.0, 1.0) * 32767)));
  return out;
}

std::vector<std::int16_t> wav_samples(const std::string& path) {
  std::vector<std::int16_t> out;
  for (const double x : read_wav_file(path).samples) out.push_back(std::int16_t(std::lrint(x * 32768)));
  return out;
}

// The played samples from `first` on equal the expected ones, as far as these go (the rendering ends
// with its trajectory; the player plays its last frames out), to the 16-bit step: render's CSV holds
// nine digits, which may round a sample to the next step.
void expect_played(const std::vector<std::int16_t>& played, std::size_t first, const std::vector<std::int16_t>& expected) {
  ASSERT_GT(played.size(), first + expected.size() / 2);
  const std::size_t n = std::min(played.size() - first, expected.size());
  std::size_t differ = 0, equal = 0;
  for (std::size_t i = 0; i < n; ++i) {
    differ += std::abs(int(played[first + i]) - int(expected[i])) > 1;
    equal += played[first + i] == expected[i];
  }
  EXPECT_EQ(differ, 0u) << "of " << n << " samples";
  EXPECT_GT(double(equal), 0.999 * double(n));
  for (std::size_t i = 0; i < first; ++i) ASSERT_EQ(played[i], 0) << "silence before the first sound, sample " << i;
}

TEST(PlayCli, ATrajectoryPlaysWhatRenderLiveRenders) {
  const TempDir dir;
  const std::string stroke = write_stroke(dir);
  for (const std::vector<std::string>& method : {std::vector<std::string>{"--reconstruct", "online", "--seed", "3"},
                                                 std::vector<std::string>{"--reconstruct", "noise", "--seed", "5"}}) {
    SCOPED_TRACE(method[1]);
    const FakeSoundCard card;
    std::vector<std::string> args = play_args({"--trajectory", stroke, "--record", dir.file("played.wav"), "--force"});
    args.insert(args.end(), method.begin(), method.end());
    const CommandResult r = run_haptex(args);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json report = nlohmann::json::parse(r.out);
    EXPECT_EQ(report["rate_hz"], 48000);
    EXPECT_EQ(report["ended_by"], "end of the trajectory");
    EXPECT_EQ(report["clock"], "haptex (the device keeps no time)");
    EXPECT_EQ(report["frames"], 120);
    const std::vector<std::int16_t> captured = card.samples();
    const std::size_t buffer = report["buffer_samples"];
    // The device got a full buffer of silence to start, then exactly what --record kept.
    const std::vector<std::int16_t> recorded = wav_samples(dir.file("played.wav"));
    ASSERT_EQ(captured.size(), buffer + recorded.size());
    EXPECT_TRUE(std::equal(recorded.begin(), recorded.end(), captured.begin() + std::ptrdiff_t(buffer)));
    EXPECT_EQ(read_wav_file(dir.file("played.wav")).info.samplerate, 48000);
    expect_played(recorded, report["first_sound_sample"], rendered_as_played(dir, stroke, method));
  }
}

// A child haptex whose standard input is a pipe the test writes to.
struct Piped {
  int pid = -1, input = -1;
  Piped(const std::vector<std::string>& args, const std::string& out, const std::string& err = "/dev/null") {
    int fds[2];
    EXPECT_EQ(::pipe(fds), 0);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[0], 0);
    posix_spawn_file_actions_addclose(&actions, fds[1]);
    posix_spawn_file_actions_addopen(&actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&actions, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    std::vector<std::string> full = {haptex_binary()};
    full.insert(full.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& a : full) argv.push_back(a.data());
    argv.push_back(nullptr);
    EXPECT_EQ(posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ), 0);
    posix_spawn_file_actions_destroy(&actions);
    ::close(fds[0]);
    input = fds[1];
    ::signal(SIGPIPE, SIG_IGN);  // after the spawn: once haptex has stopped, a write fails (EPIPE) instead of killing the test

  }
  // Writes `lines` lines of `force speed`, one per millisecond on the clock; -1: until told to stop.
  void stream(int lines, const std::atomic<bool>* stop = nullptr) const {
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; lines < 0 || i < lines; ++i) {
      if (stop && *stop) break;
      std::this_thread::sleep_until(start + std::chrono::milliseconds(i));
      char line[64];
      const int n = std::snprintf(line, sizeof line, "%.4f %.3f\n", 1.2 + 0.6 * std::sin(i / 190.0), 120 + 80 * std::sin(i / 330.0));
      if (::write(input, line, std::size_t(n)) != n) break;
    }
  }
  int finish() {
    ::close(input);
    int status = 0;
    ::waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }
};

TEST(PlayCli, AStreamAt1kHzPlaysWithoutAnUnderrunAndItsRecordingReplays) {
  const TempDir dir;
  const FakeSoundCard card;
  Piped play(play_args({"--actions", "-", "--record", dir.file("session.wav"), "--reconstruct", "online", "--seed", "7"}),
             dir.file("out.json"));
  // A line is the action of the moment it arrives: lines sent while haptex starts all arrive at once.
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  play.stream(1500);
  ASSERT_EQ(play.finish(), 0);
  const nlohmann::json report = nlohmann::json::parse(std::ifstream(dir.file("out.json")));
  EXPECT_EQ(report["ended_by"], "end of the input");
  EXPECT_EQ(report["underruns"], 0) << report.dump();
  EXPECT_GT(report["frames"], 120) << "1.5 s of actions, and 50 ms played out";
  EXPECT_LE(report["frames"], 156);
  // The session, played again offline from the actions it kept, sounds as it played.
  const std::vector<std::int16_t> recorded = wav_samples(dir.file("session.wav"));
  expect_played(recorded, report["first_sound_sample"],
                rendered_as_played(dir, dir.file("session.csv"), {"--reconstruct", "online", "--seed", "7"}));
}

// Review 11, F1: lines read at once each took a sample of their own, so a burst of thousands delayed
// every later action by its length. They share the moment they arrived; a line 300 ms later is played
// 300 ms after them.
TEST(PlayCli, ABurstOfLinesIsOneMomentNotABacklog) {
  const TempDir dir;
  const FakeSoundCard card;
  Piped play(play_args({"--actions", "-", "--record", dir.file("s.wav")}), dir.file("out.json"));
  std::string burst;
  for (int i = 0; i < 20000; ++i) burst += "1 50\n";
  ASSERT_EQ(::write(play.input, burst.data(), burst.size()), ssize_t(burst.size()));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  ASSERT_EQ(::write(play.input, "5 200\n", 6), 6);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  ASSERT_EQ(play.finish(), 0);
  std::ifstream csv(dir.file("s.csv"));
  std::string line;
  std::getline(csv, line);
  double when = -1;
  while (std::getline(csv, line))
    if (std::stod(line.substr(line.find(',') + 1)) > 4) {
      when = std::stod(line);
      break;
    }
  EXPECT_GT(when, 0.2) << "the line sent 300 ms after the burst";
  EXPECT_LT(when, 0.5) << "not 2 s later, behind 20 000 lines of 0.1 ms";
}

// Until the device has been given `periods` periods after its starting buffer (at most 20 s: a loaded machine).
void wait_for_periods(const FakeSoundCard& card, std::size_t periods) {
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  const std::uintmax_t bytes = (1440 + periods * 480) * 2;
  while (std::chrono::steady_clock::now() < give_up) {
    std::error_code ec;
    if (fs::file_size(card.raw(), ec) >= bytes && !ec) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

TEST(PlayCli, CtrlCStopsAndKeepsTheRecording) {
  const TempDir dir;
  const FakeSoundCard card;
  Piped play(play_args({"--actions", "-", "--record", dir.file("s.wav")}), dir.file("out.json"));
  std::atomic<bool> stop{false};
  std::thread writer([&] { play.stream(-1, &stop); });
  wait_for_periods(card, 30);
  ::kill(play.pid, SIGINT);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  stop = true;
  writer.join();
  EXPECT_EQ(play.finish(), 0);
  const nlohmann::json report = nlohmann::json::parse(std::ifstream(dir.file("out.json")));
  EXPECT_EQ(report["ended_by"], "interrupted");
  EXPECT_GE(report["frames"], 30);
  EXPECT_EQ(read_wav_file(dir.file("s.wav")).samples.size(), std::size_t(report["samples_played"]));
  EXPECT_TRUE(fs::exists(dir.file("s.csv")));
}

TEST(PlayCli, ABadLineStopsWithItsPlaceAndKeepsWhatWasPlayed) {
  const TempDir dir;
  const FakeSoundCard card;
  Piped play(play_args({"--actions", "-", "--record", dir.file("s.wav")}), dir.file("out.json"), dir.file("err.txt"));
  play.stream(300);  // on a loaded machine they may all come before haptex reads: then they play as one action
  ASSERT_EQ(::write(play.input, "1.0 nan\n", 8), 8);
  const int code = play.finish();
  EXPECT_EQ(code, 2);
  std::stringstream err;
  err << std::ifstream(dir.file("err.txt")).rdbuf();
  EXPECT_NE(err.str().find("standard input: line 301: 'nan' is not a finite number"), std::string::npos) << err.str();
  EXPECT_TRUE(fs::exists(dir.file("s.wav")));
  EXPECT_TRUE(fs::exists(dir.file("s.csv")));
}

TEST(PlayCli, ADeviceThatDoesNotExistIsNamed) {
  const FakeSoundCard card;
  const TempDir dir;
  const CommandResult r = run_haptex({"play", quick_model(false), "--material", material(), "--trajectory", write_stroke(dir),
                                      "--device", "no_such_card"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("no_such_card"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--device"), std::string::npos) << r.err;
}

// `--device default` on a machine whose default device is a sound server (PulseAudio here, as on a
// desktop) with a sink that keeps time, as a card does: the player is paced by the device, takes as
// long as what it plays, and the sink plays every sample --record kept, in order, none lost or changed.
TEST(PlayOnSoundServer, DefaultPlaysEverySampleAtTheDevicesPace) {
  SoundServer server;
  if (!server.missing().empty()) GTEST_SKIP() << server.missing();
  const TempDir dir;
  const auto start = std::chrono::steady_clock::now();
  const CommandResult r = run_haptex({"--json", "play", quick_model(false), "--material", material(), "--trajectory", write_stroke(dir),
                                      "--device", "default", "--buffer-ms", "100", "--full-scale", "20", "--record", dir.file("played.wav")});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json report = nlohmann::json::parse(r.out);
  EXPECT_EQ(report["clock"], "device");
  const std::vector<std::int16_t> played = wav_samples(dir.file("played.wav"));
  EXPECT_GE(seconds, 0.95 * double(played.size()) / 48000) << "paced by the device: as long as what it played";
  const std::vector<std::int16_t> heard = server.stop_and_take();
  // The sink's recording starts before the player and ends after it: silence, the buffer's silence,
  // then every played sample.
  const std::size_t sound = std::size_t(std::find_if(played.begin(), played.end(), [](std::int16_t x) { return x != 0; }) - played.begin());
  const auto first = std::find_if(heard.begin(), heard.end(), [](std::int16_t x) { return x != 0; });
  ASSERT_LT(sound, played.size());
  ASSERT_NE(first, heard.end()) << "the sink played nothing";
  const std::size_t from = std::size_t(first - heard.begin());
  ASSERT_GE(heard.size() - from, played.size() - sound) << "samples are missing at the end";
  EXPECT_TRUE(std::equal(played.begin() + std::ptrdiff_t(sound), played.end(), first)) << "the sink played other samples than --record kept";
  EXPECT_EQ(report["underruns"], 0) << "with a 100 ms buffer";
}

}  // namespace
}  // namespace haptex::test
