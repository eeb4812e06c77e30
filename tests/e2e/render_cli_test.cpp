// haptex render as a user runs it: a model trained on the small pipeline, a stroke trajectory, and
// the WAV (read back with libsndfile and, when present, Python) and CSV it writes.
#include <gtest/gtest.h>
#include <sndfile.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <sstream>

#include "core/json/schema.hpp"
#include "core/temporary_name.hpp"
#include "tests/support/quick_models.hpp"
#include "tests/support/run_haptex.hpp"
#include "tests/support/small_pipeline.hpp"
#include "tests/support/wav_file.hpp"

namespace haptex::test {
namespace {
namespace fs = std::filesystem;

std::string trained(bool per_material) { return quick_model(per_material); }

std::string material() { return json::read_file(small_pipeline().split)["materials"][0]["id"]; }

// n samples of a stroke: speed swinging 40..240 mm/s, force 0.7..2.3 N (or constant values).
std::string write_trajectory(const TempDir& dir, std::size_t n, double force = -1, double speed = -1,
                             const std::string& name = "traj.csv") {
  const std::string path = dir.file(name);
  std::ofstream csv(path);
  csv << "time_s,force,speed\n";
  for (std::size_t i = 0; i < n; ++i) {
    const double t = double(i) * 1e-4;
    csv << t << "," << (force >= 0 ? force : 1.5 + 0.8 * std::sin(2 * std::numbers::pi * 0.3 * t + 1)) << ","
        << (speed >= 0 ? speed : 140 + 100 * std::sin(2 * std::numbers::pi * 0.7 * t)) << "\n";
  }
  return path;
}

std::vector<std::string> render_args(const std::string& trajectory, const std::string& out, std::vector<std::string> more = {}) {
  std::vector<std::string> args = {"render", trained(false), "--material", material(), "--trajectory", trajectory, "-o", out};
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

// The accel_m_s2 column (the 4th) of the render CSV.
std::vector<double> csv_acceleration(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "time_s,force_n,speed_mm_s,accel_m_s2");
  std::vector<double> out;
  while (std::getline(in, line)) out.push_back(std::stod(line.substr(line.rfind(',') + 1)));
  return out;
}

void expect_nothing_written(const TempDir& dir) {
  EXPECT_FALSE(fs::exists(dir.file("out.wav")));
  EXPECT_TRUE(temporaries_of(dir.file("out.wav")).empty());
  EXPECT_FALSE(fs::exists(dir.file("out.csv")));
  EXPECT_TRUE(temporaries_of(dir.file("out.csv")).empty());
}

TEST(RenderCli, WritesATenKilohertzWavWhoseGainMatchesTheCsv) {
  const TempDir dir;
  const std::string traj = write_trajectory(dir, 12345);
  const CommandResult r = run_haptex(render_args(traj, dir.file("out.wav"), {"--csv", dir.file("out.csv")}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("wrote " + dir.file("out.wav") + " and " + dir.file("out.csv") + ": 12345 samples, 1.234 s"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("fgla 100 iterations"), std::string::npos) << r.out;
  EXPECT_TRUE(temporaries_of(dir.file("out.wav")).empty());
  EXPECT_TRUE(temporaries_of(dir.file("out.csv")).empty());

  const WavFile wav = read_wav_file(dir.file("out.wav"));
  EXPECT_EQ(wav.info.samplerate, 10000);
  EXPECT_EQ(wav.info.channels, 1);
  EXPECT_EQ(wav.info.format, SF_FORMAT_WAV | SF_FORMAT_PCM_24);
  ASSERT_EQ(wav.samples.size(), 12345u);
  const double gain = wav.full_scale();
  ASSERT_TRUE(std::isfinite(gain)) << wav.comment;
  char printed[64];
  std::snprintf(printed, sizeof printed, "full scale %.9g m/s^2", gain);
  EXPECT_NE(r.out.find(printed), std::string::npos) << "the printed gain is the file's: " << wav.comment << "\n" << r.out;
  const std::vector<double> accel = csv_acceleration(dir.file("out.csv"));
  ASSERT_EQ(accel.size(), 12345u);
  double peak = 0, energy = 0;
  for (std::size_t n = 0; n < accel.size(); ++n) {
    ASSERT_NEAR(wav.samples[n] * gain, accel[n], gain * 0x1p-22) << n;
    peak = std::max(peak, std::abs(accel[n]));
    energy += accel[n] * accel[n];
  }
  EXPECT_GT(energy, 0.0);
  EXPECT_LE(peak, gain);
  EXPECT_GT(peak, 0.99 * gain);

  // Python's readers agree on rate, length and the 24-bit peak.
  if (!python_has("wave")) GTEST_SKIP() << "no python3: Python read-back skipped";
  const std::string py_wave =
      "import wave, sys; w = wave.open(sys.argv[1]); d = w.readframes(w.getnframes()); "
      "s = [int.from_bytes(d[i:i + 3], 'little', signed=True) for i in range(0, len(d), 3)]; "
      "print(w.getframerate(), w.getnframes(), w.getnchannels(), w.getsampwidth(), max(abs(x) for x in s) / 2**23)";
  const CommandResult py = run_python({"-c", py_wave, dir.file("out.wav")});
  ASSERT_EQ(py.exit_code, 0) << py.err;
  std::istringstream fields(py.out);
  int rate = 0, frames = 0, channels = 0, width = 0;
  double py_peak = 0;
  fields >> rate >> frames >> channels >> width >> py_peak;
  EXPECT_EQ(rate, 10000);
  EXPECT_EQ(frames, 12345);
  EXPECT_EQ(channels, 1);
  EXPECT_EQ(width, 3);
  EXPECT_NEAR(py_peak * gain, peak, gain * 0x1p-22);
  if (python_has("scipy.io.wavfile")) {
    const CommandResult sp =
        run_python({"-c", "import sys, scipy.io.wavfile as w; r, x = w.read(sys.argv[1]); print(r, len(x), x.ndim)", dir.file("out.wav")});
    ASSERT_EQ(sp.exit_code, 0) << sp.err;
    EXPECT_EQ(sp.out, "10000 12345 1\n");
  }
}

nlohmann::json render_json(const TempDir& dir, const std::string& traj, const std::string& name, std::vector<std::string> more) {
  more.push_back("--json");
  const CommandResult r = run_haptex(render_args(traj, dir.file(name), more));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return r.exit_code == 0 ? nlohmann::json::parse(r.out) : nlohmann::json::object();
}

// How consistent each rendering is with the predicted spectra: FGLA's 100 iterations beat the online
// reconstruction (by little: predicted spectra are expected values that no signal has exactly, and
// both methods end near that floor), which beats the random initial phase (0 iterations) by far,
// in SC and in spectral distance; live mode is the online rendering delayed by its latency (30 ms)
// and a sample.
TEST(RenderCli, SpectralConvergenceOrdersTheReconstructions) {
  const TempDir dir;
  const std::string traj = write_trajectory(dir, 20000);
  const nlohmann::json fgla = render_json(dir, traj, "fgla.wav", {});
  // Steady: the reconstruction's own consistency (the default scatter moves it off the prediction on purpose).
  const nlohmann::json online = render_json(dir, traj, "online.wav", {"--reconstruct", "online", "--steady"});
  const nlohmann::json random = render_json(dir, traj, "random.wav", {"--iterations", "0"});
  const nlohmann::json live = render_json(dir, traj, "live.wav", {"--live", "--steady"});
  ASSERT_TRUE(fgla.contains("spectral_convergence_db") && online.contains("spectral_convergence_db") &&
              random.contains("spectral_convergence_db") && live.contains("spectral_convergence_db"));
  const double sc_fgla = fgla["spectral_convergence_db"], sc_online = online["spectral_convergence_db"],
               sc_random = random["spectral_convergence_db"];
  const double d_fgla = fgla["spectral_distance_m_s2"], d_online = online["spectral_distance_m_s2"],
               d_random = random["spectral_distance_m_s2"];
  std::printf("[ figures  ] fgla SC %.1f dB distance %.4g m/s^2 (%.3f s/s); online SC %.1f dB distance %.4g m/s^2 (%.4f s/s); "
              "random phase SC %.1f dB distance %.4g m/s^2\n",
              sc_fgla, d_fgla, fgla["compute_seconds_per_second"].get<double>(), sc_online, d_online,
              online["compute_seconds_per_second"].get<double>(), sc_random, d_random);
  EXPECT_LT(sc_fgla, -8.0);
  EXPECT_LT(sc_fgla, sc_online);
  EXPECT_LT(sc_online, sc_random - 5.0);
  EXPECT_LT(std::max(d_fgla, d_online), 0.6 * d_random);
  EXPECT_EQ(fgla["samples"], 20000);
  EXPECT_EQ(online["latency_samples"], 300);
  EXPECT_EQ(live["live"], true);
  EXPECT_EQ(live["first_frame_sample"], 500 + 300 + 1);  // the action at the frame's middle, the look-ahead, one sample
  EXPECT_NEAR(live["spectral_convergence_db"].get<double>(), sc_online, 0.5);

  const WavFile o = read_wav_file(dir.file("online.wav")), l = read_wav_file(dir.file("live.wav"));
  const double go = o.full_scale(), gl = l.full_scale();
  for (std::size_t n = 0; n < 801; ++n) ASSERT_EQ(l.samples[n], 0.0) << n;
  for (std::size_t n = 801; n < 20000; ++n) ASSERT_NEAR(l.samples[n] * gl, o.samples[n - 801] * go, (go + gl) * 0x1p-22) << n;
}

// Shaped noise: no phase search, so far from the spectra's smooth values (its windows scatter as a
// surface's do) yet at their level; live, it is the same rendering 500 + 1 samples later (no latency).
TEST(RenderCli, ShapedNoiseRendersOfflineAndLiveAlike) {
  const TempDir dir;
  const std::string traj = write_trajectory(dir, 20000);
  const nlohmann::json noise = render_json(dir, traj, "noise.wav", {"--reconstruct", "noise", "--seed", "3"});
  const nlohmann::json live = render_json(dir, traj, "live.wav", {"--live", "--reconstruct", "noise", "--seed", "3"});
  EXPECT_EQ(noise["reconstruction"], "noise");
  EXPECT_EQ(noise["latency_samples"], 0);
  EXPECT_EQ(live["first_frame_sample"], 500 + 1);
  const WavFile o = read_wav_file(dir.file("noise.wav")), l = read_wav_file(dir.file("live.wav"));
  const double go = o.full_scale(), gl = l.full_scale();
  for (std::size_t n = 0; n < 501; ++n) ASSERT_EQ(l.samples[n], 0.0) << n;
  for (std::size_t n = 501; n < 20000; ++n) ASSERT_NEAR(l.samples[n] * gl, o.samples[n - 501] * go, (go + gl) * 0x1p-22) << n;
  const nlohmann::json other = render_json(dir, traj, "other.wav", {"--reconstruct", "noise", "--seed", "4"});
  EXPECT_NE(read_wav_file(dir.file("other.wav")).samples, o.samples);
  EXPECT_GT(noise["spectral_convergence_db"].get<double>(), -12.0);  // not the expected spectrum, window by window
  EXPECT_LT(noise["spectral_convergence_db"].get<double>(), 0.0);
}

// The online method draws each frame's targets around the prediction by default: seeded, further
// from the prediction than the steady reconstruction, still far better than the random phase, and
// live it is the same rendering later by the latency and half a frame.
TEST(RenderCli, OnlineScattersByDefaultAndSteadyTurnsItOff) {
  const TempDir dir;
  const std::string traj = write_trajectory(dir, 20000);
  const nlohmann::json scattered = render_json(dir, traj, "scattered.wav", {"--reconstruct", "online", "--seed", "3"});
  const nlohmann::json steady = render_json(dir, traj, "steady.wav", {"--reconstruct", "online", "--steady"});
  const nlohmann::json live = render_json(dir, traj, "live.wav", {"--live", "--seed", "3"});
  const nlohmann::json random = render_json(dir, traj, "random.wav", {"--iterations", "0"});
  EXPECT_EQ(scattered["scatter"], true);
  EXPECT_EQ(scattered["seed"], 3);
  EXPECT_EQ(steady["scatter"], false);
  const double sc_scattered = scattered["spectral_convergence_db"], sc_steady = steady["spectral_convergence_db"],
               sc_random = random["spectral_convergence_db"];
  std::printf("[ figures  ] online SC %.1f dB scattered, %.1f dB steady; random phase %.1f dB\n", sc_scattered, sc_steady, sc_random);
  EXPECT_GT(sc_scattered, sc_steady + 3.0);
  EXPECT_LT(sc_scattered, sc_random - 2.0);
  const WavFile o = read_wav_file(dir.file("scattered.wav")), l = read_wav_file(dir.file("live.wav"));
  const double go = o.full_scale(), gl = l.full_scale();
  for (std::size_t n = 801; n < 20000; ++n) ASSERT_NEAR(l.samples[n] * gl, o.samples[n - 801] * go, (go + gl) * 0x1p-22) << n;
  render_json(dir, traj, "other.wav", {"--reconstruct", "online", "--seed", "4"});
  EXPECT_NE(read_wav_file(dir.file("other.wav")).samples, o.samples);
}

// Standing still, the model sees force and speed below its training range and saturates them:
// the rendering is finite and says so.
TEST(RenderCli, ZeroForceAndSpeedRenderFinitely) {
  const TempDir dir;
  const std::string traj = write_trajectory(dir, 3000, 0.0, 0.0);
  for (const char* method : {"fgla", "online"}) {
    const std::string out = dir.file(std::string(method) + ".wav");
    const CommandResult r = run_haptex(render_args(traj, out, {"--reconstruct", method, "--csv", out + ".csv"}));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("outside the training range"), std::string::npos) << r.err;
    for (double a : csv_acceleration(out + ".csv")) ASSERT_TRUE(std::isfinite(a));
    for (double s : read_wav_file(out).samples) ASSERT_TRUE(std::isfinite(s));
  }
}

void expect_bad_input(const CommandResult& r, const std::string& named, const TempDir& dir) {
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(named), std::string::npos) << r.err;
  expect_nothing_written(dir);
}

TEST(RenderCli, BadInputsExitTwoNamingTheFileAndLeaveNothing) {
  const TempDir dir;
  const std::string out = dir.file("out.wav"), csv = dir.file("out.csv");
  {
    const std::string traj = dir.file("no_speed.csv");
    std::ofstream(traj) << "time_s,force,velocity\n0,1,50\n0.0001,1,50\n";
    expect_bad_input(run_haptex(render_args(traj, out, {"--csv", csv})), traj, dir);
  }
  const std::string traj = write_trajectory(dir, 2000);
  {
    const std::string model = dir.file("garbage.h5");
    std::ofstream(model) << "not an HDF5 file\n";
    std::vector<std::string> args = render_args(traj, out, {"--csv", csv});
    args[1] = model;
    expect_bad_input(run_haptex(args), model, dir);
  }
  {
    const std::string image = dir.file("press.png");
    cv::Mat noise(120, 160, CV_8UC3);
    cv::randu(noise, 0, 255);
    ASSERT_TRUE(cv::imwrite(image, noise));
    const std::vector<std::string> args = {"render", trained(true), "--image", image, "--trajectory", traj, "-o", out, "--csv", csv};
    expect_bad_input(run_haptex(args), trained(true), dir);
    // The unified model takes the image.
    const std::vector<std::string> unified = {"render", trained(false), "--image", image, "--trajectory", traj, "-o", dir.file("img.wav")};
    const CommandResult ok = run_haptex(unified);
    EXPECT_EQ(ok.exit_code, 0) << ok.err;
    EXPECT_NE(ok.err.find("no --reference"), std::string::npos) << ok.err;
  }
  {
    std::vector<std::string> args = render_args(traj, out);
    args[3] = "no_such_material";
    expect_bad_input(run_haptex(args), trained(false), dir);
  }
  const std::string short_traj = write_trajectory(dir, 9, -1, -1, "short.csv");
  expect_bad_input(run_haptex(render_args(short_traj, out)), short_traj, dir);
  expect_bad_input(run_haptex(render_args(traj, out, {"--live", "--reconstruct", "fgla"})), "--live", dir);
  expect_bad_input(run_haptex(render_args(traj, out, {"--reconstruct", "online", "--iterations", "0"})), "online", dir);
  // Review 6: --steady was taken where it does nothing.
  for (const char* reconstruction : {"fgla", "noise"})
    expect_bad_input(run_haptex(render_args(traj, out, {"--reconstruct", reconstruction, "--steady"})), "--steady", dir);
  expect_bad_input(run_haptex(render_args(traj, out, {"--full-scale", "1e-9"})), out, dir);

  // An existing output is kept without --force, replaced with it.
  ASSERT_EQ(run_haptex(render_args(traj, out, {"--iterations", "2"})).exit_code, 0);
  const auto size = fs::file_size(out);
  std::ofstream(csv) << "keep me\n";
  const CommandResult again = run_haptex(render_args(traj, out, {"--iterations", "2"}));
  EXPECT_EQ(again.exit_code, 2);
  EXPECT_NE(again.err.find(out), std::string::npos) << again.err;
  EXPECT_NE(again.err.find("--force"), std::string::npos) << again.err;
  const CommandResult csv_exists = run_haptex(render_args(traj, dir.file("other.wav"), {"--csv", csv}));
  EXPECT_EQ(csv_exists.exit_code, 2);
  EXPECT_NE(csv_exists.err.find(csv), std::string::npos) << csv_exists.err;
  EXPECT_FALSE(fs::exists(dir.file("other.wav")));
  EXPECT_EQ(fs::file_size(out), size);
  EXPECT_TRUE(temporaries_of(out).empty());
  // --force replaces the WAV render wrote, never a CSV of the user's (issue 32, class 3).
  const std::vector<std::string> forced_args = render_args(traj, out, {"--iterations", "2", "--csv", csv, "--force"});
  const CommandResult refused = run_haptex(forced_args);
  EXPECT_EQ(refused.exit_code, 2) << refused.err;
  EXPECT_NE(refused.err.find(csv), std::string::npos) << refused.err;
  fs::remove(csv);
  const CommandResult forced = run_haptex(forced_args);
  EXPECT_EQ(forced.exit_code, 0) << forced.err;
  EXPECT_EQ(csv_acceleration(csv).size(), 2000u);
  EXPECT_EQ(run_haptex(forced_args).exit_code, 0) << "its own CSV is replaced";
}

}  // namespace
}  // namespace haptex::test
