// `haptex convert cluster` as a user runs it on a small tree in the Cluster database's layout
// (tests/support/cluster_tree.hpp): the recordings file follows the documented layout, each take's
// acceleration and force equal what numpy.interp and scipy's resample_poly give (h5py reads them),
// qa passes it, and a damaged tree is refused with exit code 2 and nothing written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/temporary_name.hpp"
#include "tests/support/cluster_tree.hpp"
#include "tests/support/run_haptex.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {

namespace fs = std::filesystem;

class ClusterCli : public ::testing::Test {
 protected:
  void SetUp() override {
    write_cluster_tree(dir_.file("db"), {{3, 0, 40, 500, 0}, {3, 90, 20, 1000, 1}, {12, 45, 60, 500, 0}});
    std::ofstream(dir_.file("names.csv")) << "id,name\n3,Cork board\n";
  }
  std::string out() const { return dir_.file("recordings.h5"); }
  TempDir dir_;
};

TEST_F(ClusterCli, TakesBecomeRecordingsThatScipyAgreesWith) {
  const CommandResult r =
      run_haptex({"--json", "convert", "cluster", dir_.file("db"), "-o", out(), "--names", dir_.file("names.csv")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto result = nlohmann::json::parse(r.out);
  ASSERT_EQ(result["recordings"].size(), 3u);
  EXPECT_EQ(result["recordings"][0]["material_id"], "cork_board");
  EXPECT_EQ(result["recordings"][1]["recording"], 1);
  EXPECT_EQ(result["recordings"][2]["material_id"], "cluster_12");
  if (!python_has("h5py, scipy")) GTEST_SKIP() << "python3-h5py or python3-scipy is not installed (make deps installs them)";
  const std::string scripts = std::string(HAPTEX_SCHEMA_DIR) + "/../tests/e2e/";
  const CommandResult layout = run_python({scripts + "check_layout.py", std::string(HAPTEX_SCHEMA_DIR) + "/hdf5-layout.md", out(),
                                           "Recordings"});
  EXPECT_EQ(layout.exit_code, 0) << layout.out << layout.err;
  const CommandResult same = run_python({scripts + "check_cluster.py", out(), "cork_board", "1",
                                         dir_.file("db/sensor_data/accel/3_90_20_1000_1.csv"),
                                         dir_.file("db/sensor_data/force/3_90_20_1000_1.csv")});
  EXPECT_EQ(same.exit_code, 0) << same.out << same.err;
  EXPECT_NE(same.out.find("cluster ok"), std::string::npos) << same.out;
  const CommandResult qa = run_haptex({"qa", out()});
  EXPECT_EQ(qa.exit_code, 0) << qa.out << qa.err;
}

// The whole path for Cluster data: its takes converted, aligned with GelSight presses of the same
// surfaces (named through the names file) and split. The presses here are synth's, extracted as any.
TEST(ClusterPipeline, ATreeConvertsAlignsWithPressesAndSplits) {
  const TempDir dir;
  std::vector<ClusterTakeSpec> takes;
  for (int texture : {1, 2})
    for (int velocity : {20, 40, 60})
      for (int force : {500, 1000}) takes.push_back({texture, 45 * (velocity / 20), velocity, force, 0, 3.0, 150.0 + 50 * texture, 0.3});
  write_cluster_tree(dir.file("db"), takes);
  std::ofstream(dir.file("names.json")) << R"({"1": "Polished 1", "2": "Sandpaper 1"})";
  const std::vector<std::vector<std::string>> steps{
      {"convert", "cluster", dir.file("db"), "-o", dir.file("r.h5"), "--names", dir.file("names.json")},
      {"synth", "materials", "-n", "2", "--size", "320x240", "--presses", "5", "--recordings", "1", "-o", dir.file("synth")},
      {"capture", "extract", dir.file("synth/gelsight"), "-o", dir.file("g.h5"), "--no-sheets"},
      {"align", "--recordings", dir.file("r.h5"), "--gelsight", dir.file("g.h5"), "-o", dir.file("d.h5")},
      {"split", dir.file("d.h5"), "-o", dir.file("split.json"), "--no-plots"},
      {"qa", dir.file("d.h5"), "--split", dir.file("split.json")}};
  for (const auto& step : steps) {
    const CommandResult r = run_haptex(step);
    ASSERT_EQ(r.exit_code, 0) << step[0] << ": " << r.err << r.out;
  }
  std::ifstream in(dir.file("split.json"));
  const nlohmann::json split = nlohmann::json::parse(in);
  ASSERT_EQ(split["materials"].size(), 2u);
  for (const auto& m : split["materials"]) {
    EXPECT_EQ(m["recordings"], 6) << m.dump();
    EXPECT_GT(m["windows"]["test"].get<int>(), 0) << m.dump();
  }
}

TEST_F(ClusterCli, ADamagedTreeIsRefusedAndNothingWritten) {
  const auto refused = [&](const std::vector<std::string>& mentions) {
    const CommandResult r = run_haptex({"convert", "cluster", dir_.file("db"), "-o", out()});
    EXPECT_EQ(r.exit_code, 2) << r.err;
    for (const auto& m : mentions) EXPECT_NE(r.err.find(m), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out()));
    EXPECT_TRUE(temporaries_of(out()).empty());
  };
  const std::string accel = dir_.file("db/sensor_data/accel/12_45_60_500_0.csv");
  fs::resize_file(accel, fs::file_size(accel) / 2 + 7);  // cut inside a row
  refused({accel, "fields but the header has 4"});
  write_cluster_tree(dir_.file("db"), {{12, 45, 60, 500, 0}});
  fs::remove(dir_.file("db/sensor_data/position/3_0_40_500_0.csv"));
  refused({"position/3_0_40_500_0.csv", "is missing"});
  const CommandResult no_db = run_haptex({"convert", "cluster", dir_.file("nowhere"), "-o", out()});
  EXPECT_EQ(no_db.exit_code, 2);
  EXPECT_NE(no_db.err.find("holds no sensor_data/accel folder"), std::string::npos) << no_db.err;
}

}  // namespace
}  // namespace haptex::test
