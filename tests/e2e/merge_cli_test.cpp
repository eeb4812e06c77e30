// `haptex merge` as a user runs it after converting, extracting and aligning on two machines: the
// small pipeline's files cut into one shard per material, each dataset shard aligned from its own
// recordings and gelsight shards, and merged. The merged files must hold what the unsharded files
// hold, byte for byte apart from provenance, and be accepted by info, qa and split as they are.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "core/h5/file.hpp"
#include "tests/support/run_haptex.hpp"
#include "tests/support/small_pipeline.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {

const std::string kScripts = std::string(HAPTEX_SCHEMA_DIR) + "/../tests/e2e/";

struct Sharded {
  std::vector<std::string> recordings, gelsight, dataset;  // one shard per material
  std::string merged_recordings, merged_gelsight, merged_dataset;
};

class MergeCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new TempDir;
    files_ = new Sharded;
    const SmallPipeline& p = small_pipeline();
    for (const std::string& id : material_ids(p.dataset)) {
      const std::string r = copy_with_materials(*dir_, p.recordings, "r_" + id + ".h5", {id});
      const std::string g = copy_with_materials(*dir_, p.gelsight, "g_" + id + ".h5", {id});
      const std::string d = dir_->file("d_" + id + ".h5");
      ASSERT_EQ(run_haptex({"align", "--recordings", r, "--gelsight", g, "-o", d}).exit_code, 0);
      files_->recordings.push_back(r);
      files_->gelsight.push_back(g);
      files_->dataset.push_back(d);
    }
    ASSERT_GE(files_->dataset.size(), 2u) << "the small pipeline has two materials";
    files_->merged_recordings = merged(files_->recordings, "r.h5");
    files_->merged_gelsight = merged(files_->gelsight, "g.h5");
    files_->merged_dataset = merged(files_->dataset, "d.h5");
  }
  static void TearDownTestSuite() {
    delete files_;
    delete dir_;
  }

  // Later shards first: the merged file orders materials by id whatever the shards' order.
  static std::string merged(const std::vector<std::string>& shards, const std::string& name) {
    std::vector<std::string> args = {"merge", "-o", dir_->file("merged_" + name)};
    args.insert(args.end(), shards.rbegin(), shards.rend());
    const CommandResult r = run_haptex(args);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return dir_->file("merged_" + name);
  }

  static void expect_same_content(const std::string& merged, const std::string& unsharded, std::vector<std::string> provenance) {
    if (!python_has("h5py, numpy")) GTEST_SKIP() << "python3-h5py is not installed (make deps installs it)";
    std::vector<std::string> args = {kScripts + "same_content.py", merged, unsharded, "source", "created_utc"};
    args.insert(args.end(), provenance.begin(), provenance.end());
    const CommandResult r = run_python(args);
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("same content"), std::string::npos) << r.out;
  }

  static TempDir* dir_;
  static Sharded* files_;
};

TempDir* MergeCli::dir_ = nullptr;
Sharded* MergeCli::files_ = nullptr;

TEST_F(MergeCli, MergedShardsHoldWhatTheUnshardedFilesHold) {
  const SmallPipeline& p = small_pipeline();
  expect_same_content(files_->merged_recordings, p.recordings, {});
  expect_same_content(files_->merged_gelsight, p.gelsight, {});
  expect_same_content(files_->merged_dataset, p.dataset, {"recordings_file", "recordings_sha256", "gelsight_file", "gelsight_sha256"});
}

TEST_F(MergeCli, InfoAndQaTakeAMergedFileAsAnUnshardedOne) {
  const SmallPipeline& p = small_pipeline();
  for (const auto& [merged, unsharded] : {std::pair{files_->merged_dataset, p.dataset}, std::pair{files_->merged_recordings, p.recordings},
                                          std::pair{files_->merged_gelsight, p.gelsight}}) {
    SCOPED_TRACE(merged);
    const CommandResult info = run_haptex({"info", merged, "--json"}), before = run_haptex({"info", unsharded, "--json"});
    ASSERT_EQ(info.exit_code, 0) << info.err;
    EXPECT_EQ(nlohmann::json::parse(info.out)["materials"], nlohmann::json::parse(before.out)["materials"]);
    EXPECT_EQ(nlohmann::json::parse(info.out)["other_datasets"], nlohmann::json::parse(before.out)["other_datasets"]);
    const CommandResult qa = run_haptex({"qa", merged, "--json"});
    EXPECT_EQ(qa.exit_code, 0) << qa.out << qa.err;
    EXPECT_EQ(nlohmann::json::parse(qa.out)["verdict"], nlohmann::json::parse(run_haptex({"qa", unsharded, "--json"}).out)["verdict"]);
  }
}

TEST_F(MergeCli, AMergedDatasetSplitsAndItsSplitPassesQa) {
  const TempDir dir;
  ASSERT_EQ(run_haptex({"split", files_->merged_dataset, "-o", dir.file("s.json"), "--no-plots"}).exit_code, 0);
  const CommandResult qa = run_haptex({"qa", files_->merged_dataset, "--split", dir.file("s.json")});
  EXPECT_EQ(qa.exit_code, 0) << qa.out << qa.err;
}

// What a Python user finds in the merged dataset: the documented layout, and every shard's
// provenance (its path, hash, command line and inputs' hashes).
TEST_F(MergeCli, H5pyReadsTheLayoutAndEveryShardsProvenance) {
  if (!python_has("h5py, numpy")) GTEST_SKIP() << "python3-h5py is not installed (make deps installs it)";
  const std::string layout = std::string(HAPTEX_SCHEMA_DIR) + "/hdf5-layout.md";
  for (const char* section : {"dataset/4", "Merged file"}) {
    const CommandResult r = run_python({kScripts + "check_layout.py", layout, files_->merged_dataset, section});
    EXPECT_EQ(r.exit_code, 0) << section << ": " << r.out << r.err;
  }
  const std::string script = R"(
import hashlib, sys, h5py
merged, shards = sys.argv[1], sys.argv[2:]
sha = lambda path: hashlib.sha256(open(path, "rb").read()).hexdigest()
with h5py.File(merged, "r") as f:
    assert f.attrs["source"] == "haptex merge " + " ".join(reversed(shards)), f.attrs["source"]
    inputs = []
    for s, path in enumerate(reversed(shards)):
        g = f["shards"][str(s)]
        with h5py.File(path, "r") as shard:
            assert g.attrs["file"] == path and g.attrs["sha256"] == sha(path)
            assert g.attrs["materials"].split() == list(shard["materials"]), g.attrs["materials"]
            assert g.attrs["left_out"] == ""
            for name, value in shard.attrs.items():
                assert g.attrs[name] == value, name
            assert g.attrs["source"].startswith("haptex align")
            inputs.append(shard.attrs["recordings_sha256"])
    joined = "".join(h + "\n" for h in sorted(set(inputs)))
    assert f.attrs["recordings_sha256"] == hashlib.sha256(joined.encode()).hexdigest()
    assert f.attrs["recordings_file"].split("\n") == [f["shards"][str(s)].attrs["recordings_file"] for s in range(len(shards))]
print("provenance ok")
)";
  std::vector<std::string> args = {"-c", script, files_->merged_dataset};
  args.insert(args.end(), files_->dataset.begin(), files_->dataset.end());
  const CommandResult r = run_python(args);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("provenance ok"), std::string::npos) << r.out << r.err;
}

TEST_F(MergeCli, AMaterialInTwoShardsIsRefusedUnlessKeepFirstIsGiven) {
  const TempDir dir;
  const std::string whole = small_pipeline().dataset, first = files_->dataset.front();
  const std::string id = material_ids(first).front();
  const CommandResult refused = run_haptex({"merge", first, whole, "-o", dir.file("m.h5")});
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find(whole + ": /materials/" + id + ": material '" + id + "' is also in " + first), std::string::npos) << refused.err;
  EXPECT_FALSE(std::filesystem::exists(dir.file("m.h5")));

  const CommandResult kept = run_haptex({"merge", first, whole, "-o", dir.file("m.h5"), "--keep-first", "--json"});
  ASSERT_EQ(kept.exit_code, 0) << kept.err;
  const nlohmann::json doc = nlohmann::json::parse(kept.out);
  EXPECT_EQ(doc["format"], "dataset/4");
  EXPECT_EQ(doc["left_out"], (nlohmann::json::array({{{"id", id}, {"shard", whole}, {"kept_from", first}}})));
  EXPECT_EQ(doc["windows"], h5::File::open(whole).root().open_group("windows").open_dataset("start").elements())
      << "the first shard's copy of " << id << " has the same windows as the whole file's";
  EXPECT_EQ(run_haptex({"qa", dir.file("m.h5")}).exit_code, 0);
}

}  // namespace
}  // namespace haptex::test
