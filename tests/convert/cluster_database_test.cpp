// The Cluster Haptic Texture Database reader on a small tree in its documented layout
// (tests/support/cluster_tree.hpp): takes found and ordered, irregular stamps onto 10 kHz without
// losing a tone or gravity, the speed from the positions, names from a map, and what it refuses.
#include "convert/cluster_database.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <sstream>

#include "convert/texture_names.hpp"
#include "core/error.hpp"
#include "dataset/layout.hpp"
#include "tests/support/cluster_tree.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::convert {
namespace {

namespace fs = std::filesystem;
using test::ClusterTakeSpec;

double mean(const std::vector<double>& v, std::size_t from, std::size_t to) {
  return std::accumulate(v.begin() + std::ptrdiff_t(from), v.begin() + std::ptrdiff_t(to), 0.0) / double(to - from);
}

double rms(const std::vector<double>& v, std::size_t from, std::size_t to) {
  double s = 0;
  for (std::size_t i = from; i < to; ++i) s += v[i] * v[i];
  return std::sqrt(s / double(to - from));
}

class Cluster : public ::testing::Test {
 protected:
  void SetUp() override {
    test::write_cluster_tree(dir_.path().string(), {{7, 45, 60, 500, 0}, {3, 90, 20, 1000, 1}, {3, 0, 40, 500, 0}});
  }
  std::string sensor(const std::string& folder, const std::string& take) const {
    return dir_.file("sensor_data/" + folder + "/" + take + ".csv");
  }
  void expect_refused(const std::vector<std::string>& mentions) const {
    try {
      for (const auto& take : find_cluster_takes(dir_.path().string())) read_cluster_take(take, {});
      FAIL() << "accepted";
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), Error::Kind::bad_input);
      for (const auto& m : mentions) EXPECT_NE(std::string(e.what()).find(m), std::string::npos) << e.what();
    }
  }
  test::TempDir dir_;
};

TEST_F(Cluster, FindsEveryTakeInOrderWithItsConditions) {
  const auto takes = find_cluster_takes(dir_.path().string());
  ASSERT_EQ(takes.size(), 3u);
  EXPECT_EQ(takes[0].texture, 3);
  EXPECT_EQ(takes[0].direction_deg, 0);
  EXPECT_EQ(takes[1].direction_deg, 90);
  EXPECT_EQ(takes[1].velocity_mm_s, 20);
  EXPECT_EQ(takes[1].force_mn, 1000);
  EXPECT_EQ(takes[1].repeat, 1);
  EXPECT_EQ(takes[2].texture, 7);
  EXPECT_EQ(takes[1].position, sensor("position", "3_90_20_1000_1"));
  EXPECT_EQ(find_cluster_takes(dir_.file("sensor_data")).size(), 3u) << "sensor_data itself will do";
}

TEST_F(Cluster, ATakeBecomesOneRecordingAt10kHz) {
  const auto takes = find_cluster_takes(dir_.path().string());
  const Recording r = read_cluster_take(takes[2], {{7, "Cork board"}});
  EXPECT_EQ(r.material, "Cork board");
  EXPECT_EQ(read_cluster_take(takes[0], {}).material, "cluster 3");
  EXPECT_EQ(r.sample_rate_hz, 10000.0);
  // The span all three files cover: from the first accel stamp (0.999 ms) to the last (about 1.5 s).
  EXPECT_NEAR(double(r.samples()), 14990.0, 10.0);
  const std::size_t a = 500, b = r.samples() - 500;  // away from the filter's edges
  EXPECT_NEAR(mean(r.channels.at("accel_z"), a, b), -9.80665, 1e-3) << "g to m/s^2";
  EXPECT_NEAR(rms(r.channels.at("accel_x"), a, b), 0.3 * 9.80665 / std::sqrt(2.0), 0.01) << "a 200 Hz tone keeps its size";
  EXPECT_NEAR(mean(r.channels.at(dataset::layout::kForceNormal), a, b), 0.5, 0.01);
  EXPECT_NEAR(mean(r.channels.at(dataset::layout::kSpeed), a, b), 60.0, 0.6) << "the positions' speed";
  EXPECT_EQ(r.source_numbers.at(dataset::layout::kCommandedForce), 0.5);
  EXPECT_EQ(r.source_numbers.at(dataset::layout::kStrokeDirection), 45.0);
  EXPECT_EQ(r.source_texts.at(dataset::layout::kPositionSourceFile), sensor("position", "7_45_60_500_0"));
  EXPECT_EQ(r.source_texts.at(dataset::layout::kForceSourceSha256).size(), 64u);
}

TEST_F(Cluster, RefusesWhatIsNotATakeNamingTheFileAndThePlace) {
  fs::remove(sensor("force", "3_0_40_500_0"));
  expect_refused({sensor("force", "3_0_40_500_0"), "is missing"});
  test::write_cluster_tree(dir_.path().string(), {{3, 0, 40, 500, 0}});
  std::ofstream(sensor("accel", "cork_0")) << "time,X,Y,Z\n";
  expect_refused({sensor("accel", "cork_0"), "TEXTURE_DIRECTION_VELOCITY_FORCE_REPEAT"});
  fs::remove(sensor("accel", "cork_0"));

  // Cell `column` of line `row` (0: the header) of a take's file becomes `text`.
  const auto rewrite = [&](const std::string& folder, int row, std::size_t column, const std::string& text) {
    std::ifstream in(sensor(folder, "3_0_40_500_0"));
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    std::vector<std::string> cells;
    std::stringstream cut(lines.at(std::size_t(row)));
    for (std::string cell; std::getline(cut, cell, ',');) cells.push_back(cell);
    cells.at(column) = text;
    lines[std::size_t(row)].clear();
    for (const auto& cell : cells) lines[std::size_t(row)] += (lines[std::size_t(row)].empty() ? "" : ",") + cell;
    std::ofstream out(sensor(folder, "3_0_40_500_0"));
    for (const auto& line : lines) out << line << "\n";
  };
  rewrite("accel", 1, 3, "nan");
  expect_refused({sensor("accel", "3_0_40_500_0"), "line 2, column 'Z'", "not a finite number"});
  test::write_cluster_tree(dir_.path().string(), {{3, 0, 40, 500, 0}});
  rewrite("force", 0, 1, "Fz");
  expect_refused({sensor("force", "3_0_40_500_0"), "line 1", "no 'force' column", "time,force"});
  test::write_cluster_tree(dir_.path().string(), {{3, 0, 40, 500, 0}});
  {  // the first two samples swapped: the second stamp comes before the first
    std::ifstream in(sensor("accel", "3_0_40_500_0"));
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    std::swap(lines[1], lines[2]);
    std::ofstream out(sensor("accel", "3_0_40_500_0"));
    for (const auto& line : lines) out << line << "\n";
  }
  expect_refused({sensor("accel", "3_0_40_500_0"), "line 3, column 'time'", "does not come after"});
}

TEST_F(Cluster, APositionInOtherUnitsOrAMisnamedFileIsRefused) {
  // A take stroked at 20 mm/s under the name of one at 40 mm/s.
  test::write_cluster_tree(dir_.path().string(), {{3, 0, 20, 500, 0}});
  for (const char* folder : {"accel", "force", "position"})
    fs::rename(sensor(folder, "3_0_20_500_0"), sensor(folder, "3_0_40_500_0"));
  expect_refused({sensor("position", "3_0_40_500_0"), "median speed is 20.0 mm/s where the file name says 40 mm/s"});
  test::write_cluster_tree(dir_.path().string(), {{3, 0, 40, 500, 0}});
  // Metres instead of millimetres: the stroke moves 1000 times slower than the name says.
  std::ifstream in(sensor("position", "3_0_40_500_0"));
  std::string line, text;
  std::getline(in, line);
  text = line + "\n";
  while (std::getline(in, line)) {
    double t, x, y;
    std::sscanf(line.c_str(), "%lf,%lf,%lf", &t, &x, &y);
    text += std::to_string(t) + "," + std::to_string(x / 1000) + "," + std::to_string(y / 1000) + "\n";
  }
  std::ofstream(sensor("position", "3_0_40_500_0")) << text;
  expect_refused({sensor("position", "3_0_40_500_0"), "does not move"});
}

TEST_F(Cluster, TextureNamesComeFromJsonOrCsv) {
  std::ofstream(dir_.file("names.json")) << R"({"3": "Cork board", "7": "Brick, red"})";
  std::ofstream(dir_.file("names.csv")) << "id,name\n3,Cork board\n7,\"Brick, red\"\n";
  const std::map<int, std::string> expected = {{3, "Cork board"}, {7, "Brick, red"}};
  EXPECT_EQ(read_texture_names(dir_.file("names.json")), expected);
  EXPECT_EQ(read_texture_names(dir_.file("names.csv")), expected);
  const auto refused = [&](const std::string& file, const std::string& text, const std::string& says) {
    std::ofstream(dir_.file(file)) << text;
    try {
      read_texture_names(dir_.file(file));
      ADD_FAILURE() << text;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(dir_.file(file)), std::string::npos) << e.what();
    }
  };
  refused("a.csv", "id,name\n3,Cork\n3,Cork again\n", "line 3: texture 3 is named twice");
  refused("b.csv", "id,name\nthree,Cork\n", "'three' is not a texture id");
  refused("c.json", R"({"3": 4})", "/3: the name is not a string");
  refused("d.json", "[1, 2]", "not a JSON object");
  refused("e.csv", "id,name\n3,\xff\xfe\n", "UTF-8");
  refused("f.txt", "3,Cork", "neither .json nor .csv");
  // Issue 32, classes 15 and 17.
  refused("g.json", R"({"3": "Cork", "3": "Cork again"})", "/3: the key is given twice");
  refused("h.csv", "", "names no texture");
  refused("i.csv", "id,name\n", "names no texture");
  refused("j.json", "{}", "names no texture");
  refused("k.json", std::string("{\"3\": \"Co\\u0000rk\"}"), "NUL");
  refused("l.csv", std::string(2 << 20, 'x'), "over the limit");
  // Issue 32, class 15 (second review): two names of one material id, an open quote, a leading zero.
  refused("m.json", R"({"3": "Cork", "5": "cork"})", "make one material id, 'cork'");
  refused("n.csv", "id,name\n3,\"Cork\n", "line 2: the name's quotes are not closed");
  refused("o.json", R"({"03": "Cork"})", "/03: '03' is written with a leading zero");
  // Review 9, F3: a name that makes no id was refused naming a take's accel file, not this file.
  refused("p.json", R"({"3": "***"})", "texture 3: '***' has no letter or digit");
}

// Review 9, F3: texture 1 named "cluster 2" joined texture 2's takes (default name "cluster 2").
TEST_F(Cluster, ANameThatAnotherTexturesDefaultMakesIsRefused) {
  std::vector<ClusterTake> takes(3);
  takes[0].texture = 1, takes[1].texture = 2, takes[2].texture = 2;
  EXPECT_NO_THROW(check_cluster_materials(takes, {{1, "Cork"}}, "names.json"));
  EXPECT_NO_THROW(check_cluster_materials(takes, {{2, "cluster 2"}}, "names.json")) << "a texture may be named as its default";
  for (const std::map<int, std::string>& names : {std::map<int, std::string>{{1, "cluster 2"}}, std::map<int, std::string>{{2, "Cluster-1"}}}) {
    try {
      check_cluster_materials(takes, names, "names.json");
      ADD_FAILURE() << names.begin()->second << " was taken";
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), Error::Kind::bad_input);
      const std::string other = names.begin()->first == 1 ? "2" : "1";
      EXPECT_NE(std::string(e.what()).find("names.json: texture " + std::to_string(names.begin()->first) + ": "), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("that texture " + other + " has by default"), std::string::npos) << e.what();
    }
  }
}

// Review 10, F4: a names file naming none of the database's textures (another database's) was taken,
// every material then named by default; one naming some absent textures says which.
TEST_F(Cluster, ANamesFileOfAnotherDatabaseIsRefused) {
  std::vector<ClusterTake> takes(2);
  takes[0].texture = 1, takes[1].texture = 3;
  try {
    check_cluster_materials(takes, {{9, "Unused"}}, "names.json");
    ADD_FAILURE() << "a names file of another database was taken";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::bad_input);
    EXPECT_NE(std::string(e.what()).find("names.json: names none of the database's textures (it holds 1, 3)"), std::string::npos) << e.what();
  }
  EXPECT_EQ(check_cluster_materials(takes, {{1, "Cork"}, {9, "Unused"}, {12, "Felt"}}, "names.json"), (std::vector<int>{9, 12}));
  EXPECT_EQ(check_cluster_materials(takes, {{1, "Cork"}, {3, "Felt"}}, "names.json"), std::vector<int>{});
}

TEST_F(Cluster, ANamesFileThatNeverEndsIsRefused) {
  fs::create_symlink("/dev/zero", dir_.file("zero.csv"));
  try {
    read_texture_names(dir_.file("zero.csv"));
    ADD_FAILURE() << "/dev/zero was read as names";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("not a regular file"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace haptex::convert
