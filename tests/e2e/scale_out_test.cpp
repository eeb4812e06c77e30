// docs/scale-out.md as a test: 4 shards (one material each) converted, extracted and aligned as 4
// processes running at once, then merged, must give the dataset one run over the whole collection
// gives (same windows, same values; tests/e2e/same_content.py) and the same split for a seed.
#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <future>
#include <nlohmann/json.hpp>

#include "core/json/schema.hpp"
#include "tests/support/run_haptex.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {
namespace fs = std::filesystem;

const std::string kScripts = std::string(HAPTEX_SCHEMA_DIR) + "/../tests/e2e/";

// One shard's commands, in order, as one node runs them; the first failure's message, or "".
std::string run_shard(const std::vector<std::vector<std::string>>& steps) {
  for (const auto& step : steps)
    if (const CommandResult r = run_haptex(step); r.exit_code != 0) return step[0] + ": " + r.err;
  return "";
}

// The split's assignment (sections and presses per material), without the file paths and hashes.
nlohmann::json assignment(const std::string& split) {
  const nlohmann::json doc = json::read_file(split);
  nlohmann::json out;
  for (const auto& m : doc["materials"]) out[m["id"].get<std::string>()] = {m["sections"], m["presses"]};
  return out;
}

TEST(ScaleOut, FourShardsRunAtOnceMergeIntoTheDatasetOfOneRun) {
  if (!python_has("h5py, numpy")) GTEST_SKIP() << "python3-h5py is not installed (make deps installs it)";
  const TempDir dir;
  const std::string synth = dir.file("synth");
  ASSERT_EQ(run_haptex({"synth", "materials", "-n", "4", "--size", "320x240", "--presses", "5", "--recordings", "1", "--seconds", "3", "-o",
                        synth, "-q"}).exit_code, 0);
  // One run over the whole collection.
  ASSERT_EQ(run_shard({{"convert", "hatt", synth + "/recordings", "-o", dir.file("r.h5")},
                       {"capture", "extract", synth + "/gelsight", "-o", dir.file("g.h5"), "--no-sheets"},
                       {"align", "--recordings", dir.file("r.h5"), "--gelsight", dir.file("g.h5"), "-o", dir.file("d.h5")}}),
            "");
  // A shard per material folder, all four at once.
  std::vector<std::future<std::string>> shards;
  std::vector<std::string> datasets;
  int n = 0;
  for (const auto& folder : fs::directory_iterator(synth + "/gelsight")) {
    const std::string material = folder.path().filename().string(), out = dir.file("shard" + std::to_string(n++));
    fs::create_directories(out);
    std::string xml = material;  // synth writes material "Brushed 1"'s recording as brushed_1_0.xml.gz
    for (char& c : xml) c = c == ' ' ? '_' : char(std::tolower(static_cast<unsigned char>(c)));
    xml = synth + "/recordings/" + xml + "_0.xml.gz";
    ASSERT_TRUE(fs::exists(xml)) << xml;
    datasets.push_back(out + "/dataset.h5");
    shards.push_back(std::async(std::launch::async, run_shard,
                                std::vector<std::vector<std::string>>{
                                    {"convert", "hatt", xml, "-o", out + "/recordings.h5"},
                                    {"capture", "extract", folder.path().string(), "-o", out + "/gelsight.h5", "--no-sheets"},
                                    {"align", "--recordings", out + "/recordings.h5", "--gelsight", out + "/gelsight.h5", "-o", datasets.back()}}));
  }
  ASSERT_EQ(shards.size(), 4u);
  for (auto& s : shards) EXPECT_EQ(s.get(), "");
  std::vector<std::string> merge{"merge", "-o", dir.file("merged.h5")};
  merge.insert(merge.end(), datasets.begin(), datasets.end());
  const CommandResult merged = run_haptex(merge);
  ASSERT_EQ(merged.exit_code, 0) << merged.err;

  const CommandResult same = run_python({kScripts + "same_content.py", dir.file("merged.h5"), dir.file("d.h5"), "source", "created_utc",
                                         "recordings_file", "recordings_sha256", "gelsight_file", "gelsight_sha256"});
  EXPECT_EQ(same.exit_code, 0) << same.out << same.err;
  EXPECT_NE(same.out.find("same content"), std::string::npos) << same.out;
  for (const char* file : {"merged.h5", "d.h5"})
    ASSERT_EQ(run_haptex({"split", dir.file(file), "-o", dir.file(std::string(file) + ".json"), "--seed", "7", "--no-plots"}).exit_code, 0);
  EXPECT_EQ(assignment(dir.file("merged.h5.json")), assignment(dir.file("d.h5.json")));
  EXPECT_EQ(assignment(dir.file("d.h5.json")).size(), 4u);
}

}  // namespace
}  // namespace haptex::test
