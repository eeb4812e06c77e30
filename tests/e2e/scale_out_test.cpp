// docs/scale-out.md as a test: 4 shards (one material each) converted, extracted and aligned as 4
// processes running at once, then merged, must give the dataset one run over the whole collection
// gives (same windows, same values; tests/e2e/same_content.py) and the same split for a seed.
#include <gtest/gtest.h>

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
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

// Merges the shards' datasets into dir/merged.h5 and checks it holds what one run made in dir/d.h5:
// the same materials, recordings, presses and windows, apart from provenance.
void expect_merge_of_shards_is_one_run(const TempDir& dir, const std::vector<std::string>& datasets) {
  std::vector<std::string> merge{"merge", "-o", dir.file("merged.h5")};
  merge.insert(merge.end(), datasets.begin(), datasets.end());
  const CommandResult merged = run_haptex(merge);
  ASSERT_EQ(merged.exit_code, 0) << merged.err;
  const CommandResult same = run_python({kScripts + "same_content.py", dir.file("merged.h5"), dir.file("d.h5"), "source", "created_utc",
                                         "recordings_file", "recordings_sha256", "gelsight_file", "gelsight_sha256"});
  EXPECT_EQ(same.exit_code, 0) << same.out << same.err;
  EXPECT_NE(same.out.find("same content"), std::string::npos) << same.out;
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
  expect_merge_of_shards_is_one_run(dir, datasets);
  for (const char* file : {"merged.h5", "d.h5"})
    ASSERT_EQ(run_haptex({"split", dir.file(file), "-o", dir.file(std::string(file) + ".json"), "--seed", "7", "--no-plots"}).exit_code, 0);
  EXPECT_EQ(assignment(dir.file("merged.h5.json")), assignment(dir.file("d.h5.json")));
  EXPECT_EQ(assignment(dir.file("d.h5.json")).size(), 4u);
}

// The recipe as a user runs it (docs/scale-out.md): examples/scale-out/shards.sh under `xargs -P 2` on a
// collection laid out as the doc says, haptex found on PATH, then merged; the merged /windows are one
// run's. A shard beyond the materials stops with exit code 2 before any work.
TEST(ScaleOut, TheShardScriptUnderXargsGivesTheWindowsOfOneRun) {
  if (!python_has("h5py, numpy")) GTEST_SKIP() << "python3-h5py is not installed (make deps installs it)";
  if (run_program({"bash", "--version"}).exit_code != 0) GTEST_SKIP() << "bash is missing";
  const TempDir dir;
  const std::string synth = dir.file("synth");
  ASSERT_EQ(run_haptex({"synth", "materials", "-n", "3", "--size", "320x240", "--presses", "5", "--recordings", "1", "--seconds", "3", "-o",
                        synth, "-q"}).exit_code, 0);
  // collection/{recordings,presses}/<Material>/ ("Brushed 1": names with spaces), in a folder whose name has one too.
  const std::string collection = dir.file("my collection");
  fs::create_directories(collection + "/presses");
  fs::create_directories(dir.file("elsewhere"));
  bool linked = false;  // one material's presses gathered by a link (review 21, F5: the script passed it over)
  for (const auto& folder : fs::directory_iterator(synth + "/gelsight")) {
    const std::string material = folder.path().filename().string();
    std::string xml = material;
    for (char& c : xml) c = c == ' ' ? '_' : char(std::tolower(static_cast<unsigned char>(c)));
    fs::create_directories(collection + "/recordings/" + material);
    fs::copy_file(synth + "/recordings/" + xml + "_0.xml.gz", collection + "/recordings/" + material + "/" + xml + "_0.xml.gz");
    if (!linked) {
      fs::copy(folder.path(), dir.file("elsewhere/" + material), fs::copy_options::recursive);
      fs::create_directory_symlink(dir.file("elsewhere/" + material), collection + "/presses/" + material);
      linked = true;
    } else {
      fs::copy(folder.path(), collection + "/presses/" + material, fs::copy_options::recursive);
    }
  }
  // One run over the whole collection.
  ASSERT_EQ(run_shard({{"convert", "hatt", collection + "/recordings", "-o", dir.file("r.h5")},
                       {"capture", "extract", collection + "/presses", "-o", dir.file("g.h5"), "--no-sheets"},
                       {"align", "--recordings", dir.file("r.h5"), "--gelsight", dir.file("g.h5"), "-o", dir.file("d.h5")}}),
            "");
  const std::string path = fs::path(haptex_binary()).parent_path().string() + ":" + std::getenv("PATH");
  const std::string script = std::string(HAPTEX_SCHEMA_DIR) + "/../examples/scale-out/shards.sh";
  const auto shards = [&](int count, const std::string& indices) {
    std::ofstream(dir.file("indices")) << indices;
    return run_program({"xargs", "-P", "2", "-I{}", "-a", dir.file("indices"), "env", "PATH=" + path, "COLLECTION=" + collection,
                        "OUT=" + dir.file("shards"), "SHARD={}", "SHARDS=" + std::to_string(count), script},
                       dir.path());
  };
  const CommandResult r = shards(3, "0\n1\n2\n");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  expect_merge_of_shards_is_one_run(dir, {dir.file("shards/0/dataset.h5"), dir.file("shards/1/dataset.h5"), dir.file("shards/2/dataset.h5")});
  // More shards than materials: the fourth has none and says so, exit 2 (xargs then 123).
  const CommandResult empty = shards(4, "3\n");
  EXPECT_EQ(empty.exit_code, 123) << empty.err;
  EXPECT_NE(empty.err.find("shard 3 of 4 has no materials"), std::string::npos) << empty.err;
  EXPECT_FALSE(fs::exists(dir.file("shards/3")));
  // Without haptex on PATH, before any work.
  std::ofstream(dir.file("indices")) << "0\n";
  const CommandResult unfound = run_program({"env", "PATH=/usr/bin:/bin", "SHARD=0", "SHARDS=1", "COLLECTION=" + collection, script}, dir.path());
  EXPECT_EQ(unfound.exit_code, 2);
  EXPECT_NE(unfound.err.find("haptex is not on PATH"), std::string::npos) << unfound.err;
  // 010 is no shard number (bash would take it as octal 8 and build shard 8 into OUT/010).
  const CommandResult octal = run_program({"env", "PATH=" + path, "SHARD=010", "SHARDS=10", "COLLECTION=" + collection, script}, dir.path());
  EXPECT_EQ(octal.exit_code, 2);
  EXPECT_NE(octal.err.find("plain decimals"), std::string::npos) << octal.err;
}

}  // namespace
}  // namespace haptex::test
