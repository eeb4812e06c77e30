// Single checks called on their own, with data built in memory or read from the small pipeline and
// changed in memory: each fails on its defect and passes without it, in the branches the file
// mutations of the other qa tests do not reach.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "qa/gelsight_checks.hpp"
#include "qa/recording_checks.hpp"
#include "qa/split_checks.hpp"
#include "tests/qa/qa_fixture.hpp"
#include "tests/support/random_signal.hpp"

namespace haptex::test {
namespace {

const std::string kPath = "/materials/m/recordings/0";

// n samples at 10 kHz, every signal present: a 1 Hz stroke (force 0.5 .. 1.5 N, speed 50 .. 150 mm/s),
// noise on the three axes and, as accel, their magnitude sample by sample (the axes' energy in
// every window).
qa::LoadedRecording recording(std::size_t n) {
  qa::LoadedRecording r;
  r.path = kPath;
  r.material = "m";
  r.sample_rate_hz = 10000.0;
  r.samples = std::int64_t(n);
  r.duration_s = double(n) / 10000.0;
  for (const auto& spec : qa::kSignalSpecs) {
    qa::Signal& s = r.signals[spec.name];
    s.rows = n;
    s.columns = spec.columns;
    s.values.assign(n * spec.columns, 0.0);
  }
  const std::vector<double> noise = random_signal(3 * n, 7);
  for (std::size_t i = 0; i < n; ++i) {
    double square = 0;
    for (std::size_t c = 0; c < 3; ++c) {
      r.signals["accel_xyz"].values[3 * i + c] = noise[3 * i + c];
      square += noise[3 * i + c] * noise[3 * i + c];
    }
    r.signals["accel"].values[i] = std::sqrt(square);
    const double stroke = std::sin(2 * std::numbers::pi * double(i) / 10000.0);
    r.signals["force_normal"].values[i] = 1 + 0.5 * stroke;
    r.signals["speed"].values[i] = 100 + 50 * stroke;
  }
  return r;
}

qa::CheckResult duration_result(const qa::LoadedRecording& r) {
  qa::CheckTally tally("signal.duration", "recordings");
  qa::check_signal_duration(r, tally);
  return tally.result();
}

TEST(SignalDuration, FailsUnderOneModelWindowAndPassesAtOne) {
  const qa::CheckResult short_one = duration_result(recording(999));
  EXPECT_EQ(short_one.status, qa::Status::fail);
  EXPECT_EQ(short_one.message, kPath + ": 999 samples, fewer than one model window (1000)");
  EXPECT_EQ(duration_result(recording(1000)).status, qa::Status::pass);
}

TEST(SignalForceRange, FailsBelowTheLoadCellOffsetAndQuotesTheRangeWhenPassing) {
  qa::CheckTally passing("signal.force_range", "recordings");
  qa::Seen seen;
  qa::check_signal_force_range(recording(30000), passing, seen);
  EXPECT_EQ(passing.result().status, qa::Status::pass);
  EXPECT_EQ(passing.result().message, "1 recording: force_normal ranges 0.5 .. 1.5 N");

  qa::LoadedRecording offset = recording(30000);
  for (double& f : offset.signals["force_normal"].values) f -= 1.2;
  qa::CheckTally failing("signal.force_range", "recordings");
  qa::check_signal_force_range(offset, failing, seen);
  EXPECT_EQ(failing.result().status, qa::Status::fail);
  EXPECT_EQ(failing.result().message, kPath + "/force_normal: ranges -0.7 .. 0.3 N, below -0.5 N");
}

// Review 9, C1: "1 presse checked".
TEST(CheckTally, OneItemIsNamedInTheSingular) {
  for (const auto& [items, one] : {std::pair<std::string, std::string>{"presses", "1 press checked"}, {"hashes", "1 hash checked"},
                                   {"recordings", "1 recording checked"}, {"references", "1 reference checked"}}) {
    qa::CheckTally tally("signal.duration", items);
    tally.pass();
    EXPECT_EQ(tally.result().message, one);
  }
}

qa::CheckResult reduction_result(const qa::LoadedRecording& r) {
  qa::CheckTally tally("signal.reduction_energy", "recordings");
  qa::Seen ratio{INFINITY, 0};
  qa::check_signal_reduction_energy(r, tally, ratio);
  return tally.result();
}

TEST(SignalReductionEnergy, FailsOnAWindowThatGainedEnergyAndPassesWhenEveryWindowKeepsIt) {
  qa::LoadedRecording r = recording(30000);
  const qa::CheckResult kept = reduction_result(r);
  EXPECT_EQ(kept.status, qa::Status::pass);
  EXPECT_EQ(kept.message, "1 recording: every 100 ms window of accel holds 1 to 1 x the axes' energy");

  for (std::size_t i = 5000; i < 6000; ++i) r.signals["accel"].values[i] *= 2;
  const qa::CheckResult gained = reduction_result(r);
  EXPECT_EQ(gained.status, qa::Status::fail);
  EXPECT_EQ(gained.where, std::vector<std::string>{kPath + "/accel"});
  EXPECT_NE(gained.message.find("the 100 ms window at sample 5000 holds 4 x"), std::string::npos) << gained.message;
}

TEST(SignalReductionEnergy, LeavesQuietWindowsUnjudged) {
  qa::LoadedRecording r = recording(30000);
  // The sensor's floor at a stroke's turn: a thousandth of the axes' amplitude, and accel lost there.
  for (std::size_t i = 5000; i < 6000; ++i) {
    for (std::size_t c = 0; c < 3; ++c) r.signals["accel_xyz"].values[3 * i + c] *= 1e-3;
    r.signals["accel"].values[i] = 0;
  }
  EXPECT_EQ(reduction_result(r).status, qa::Status::pass);
}

qa::Press press(const std::string& material, int j, cv::Size reference, cv::Size peak) {
  qa::Press p;
  p.path = "/materials/" + material + "/presses/" + std::to_string(j);
  p.material = material;
  p.has_reference = p.has_peak = true;
  p.reference_size = reference;
  p.peak_size = p.frames_size = peak;
  p.sizes_agree = reference == peak;
  return p;
}

TEST(GelsightResolution, FailsOnAPressWhoseImagesDifferInSizeAndPassesWhenTheyAgree) {
  const cv::Size full(160, 120), half(80, 60);
  qa::GelsightPresses file{{press("m", 0, full, full), press("m", 1, full, full)}, {{"m", 2}}};
  const qa::CheckResult agree = qa::check_gelsight_resolution(file);
  EXPECT_EQ(agree.status, qa::Status::pass) << agree.message;

  file.presses[1] = press("m", 1, full, half);
  const qa::CheckResult differ = qa::check_gelsight_resolution(file);
  EXPECT_EQ(differ.status, qa::Status::fail);
  EXPECT_EQ(differ.message, "/materials/m/presses/1: reference, peak, frames and the press's width and height differ in size");
}

TEST(GelsightResolution, SkipsAMaterialWithoutPresses) {
  const qa::CheckResult r = qa::check_gelsight_resolution({{}, {{"m", 0}}});
  EXPECT_EQ(r.status, qa::Status::skip);
  EXPECT_EQ(r.message, "/materials/m: no readable press images");
}

// The small pipeline's manifest, changed in memory, against its dataset.
class SplitCheck : public ::testing::Test {
 protected:
  qa::SplitDataset dataset() const { return qa::open_split_dataset(m_, doc_.path, small_pipeline().dataset); }
  qa::SplitDataset no_dataset() const { return qa::open_split_dataset(m_, doc_.path, std::nullopt); }
  split::SplitManifestDocument doc_ = split::read_split_manifest(small_pipeline().split);
  split::SplitManifest m_ = split::parse_split_manifest(doc_.json);
};

TEST_F(SplitCheck, MaterialListedTwiceIsSplitMaterialsEvenWithoutTheDataset) {
  EXPECT_EQ(qa::check_split_materials(m_, dataset()).status, qa::Status::pass);
  const qa::CheckResult alone = qa::check_split_materials(m_, no_dataset());
  EXPECT_EQ(alone.status, qa::Status::skip);
  EXPECT_NE(alone.message.find("was not found"), std::string::npos) << alone.message;

  m_.materials.push_back(m_.materials[0]);
  for (const qa::SplitDataset& d : {dataset(), no_dataset()}) {
    const qa::CheckResult twice = qa::check_split_materials(m_, d);
    EXPECT_EQ(twice.status, qa::Status::fail);
    EXPECT_EQ(twice.message, "#/materials/2/id: " + m_.materials[0].id + " is listed twice");
  }
}

TEST_F(SplitCheck, WorstCoverageThatIsNotTheLowestIsSplitCoverageRecorded) {
  const qa::SplitDataset d = dataset();
  const auto recount = qa::recount_windows(m_, qa::material_sections(m_), d);
  EXPECT_EQ(qa::check_split_coverage_recorded(m_, d, recount).status, qa::Status::pass);

  m_.worst_coverage -= 0.01;
  const qa::CheckResult r = qa::check_split_coverage_recorded(m_, d, recount);
  EXPECT_EQ(r.status, qa::Status::fail);
  EXPECT_EQ(r.where, std::vector<std::string>{"#/worst_coverage"});
}

TEST_F(SplitCheck, RecountNeedsTheDatasetsWindowTable) {
  const qa::SplitDataset d = no_dataset();
  const auto recount = qa::recount_windows(m_, qa::material_sections(m_), d);
  ASSERT_EQ(recount.size(), m_.materials.size());
  for (const auto& r : recount) EXPECT_FALSE(r.usable);
  for (const qa::CheckResult& r : {qa::check_split_crossing(m_, d, recount), qa::check_split_coverage(m_, d, recount),
                                   qa::check_split_coverage_recorded(m_, d, recount)}) {
    EXPECT_EQ(r.status, qa::Status::skip) << r.id;
    EXPECT_EQ(r.message, d.table_problem) << r.id;
  }
}

}  // namespace
}  // namespace haptex::test
