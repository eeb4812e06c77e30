// Issue 11 point 4: one validation of a split manifest against its dataset (the split.* checks of
// haptex qa) runs in split before it writes, and in train and evaluate before they read: a leaky,
// out-of-range or empty split is exit code 2 naming the material and the sections.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>

#include "tests/hostile/hostile_support.hpp"
#include "tests/support/mutations.hpp"
#include "tests/support/pipeline_fixture.hpp"
#include "tests/support/quick_models.hpp"
#include "tests/support/small_pipeline.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {
namespace fs = std::filesystem;

struct SplitDamage {
  std::string name;
  std::function<void(nlohmann::json& material)> edit;
  std::string says;
};

TEST(LeakySplit, TrainAndEvaluateRefuseAHandEditedManifest) {
  const std::vector<SplitDamage> damages = {
      {"a section in two sets", [](nlohmann::json& m) { m["sections"]["test"].push_back(m["sections"]["train"][0]); }, "is in both train and test"},
      {"test sections = training sections", [](nlohmann::json& m) { m["sections"]["test"] = m["sections"]["train"]; }, "is in both train and test"},
      {"a section out of range", [](nlohmann::json& m) { m["sections"]["val"].push_back(99999); }, "section 99999 in val is outside"},
      {"an empty test set", [](nlohmann::json& m) { m["sections"]["test"] = nlohmann::json::array(); }, "nothing in test"},
  };
  const SmallPipeline& p = small_pipeline();
  const std::string id = read_json(p.split)["materials"][1]["id"];
  for (const SplitDamage& damage : damages) {
    SCOPED_TRACE(damage.name);
    const TempDir dir;
    nlohmann::json manifest = read_json(p.split);
    damage.edit(manifest["materials"][1]);
    write_json(dir.file("split.json"), manifest);
    const CommandResult train = run_haptex(quick_train_args(p.dataset, dir.file("split.json"), dir.file("m.h5")));
    expect_refusal(train, {dir.file("split.json"), id, damage.says});
    EXPECT_FALSE(fs::exists(dir.file("m.h5")));
    const CommandResult evaluate =
        run_haptex({"evaluate", p.dataset, "--split", dir.file("split.json"), "--model", quick_model(), "-o", dir.file("report")});
    expect_refusal(evaluate, {dir.file("split.json"), id, damage.says});
    EXPECT_FALSE(fs::exists(dir.file("report")));
    EXPECT_EQ(partial_files(dir.path().string()), std::vector<std::string>{});
  }
}

TEST(LeakySplit, SplitRefusesSectionsSoShortEveryWindowCrossesOne) {
  const TempDir dir;
  const CommandResult r = run_haptex({"split", small_pipeline().dataset, "-o", dir.file("split.json"), "--sections", "10000", "--no-plots"});
  expect_refusal(r, {dir.file("split.json"), "nothing in train"});
  EXPECT_FALSE(fs::exists(dir.file("split.json")));
}

TEST(LeakySplit, SplitRefusesAMaterialWithOneHalfSecondRecording) {
  PipelineFiles files;
  make_pipeline_dataset(files, {0.5});
  const CommandResult r = run_haptex({"split", files.dataset, "-o", files.dir.file("split.json"), "--no-plots"});
  EXPECT_EQ(r.exit_code, 2) << r.err << r.out;
  EXPECT_NE(r.err.find("nothing in"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(files.dir.file("split.json")));
}

}  // namespace
}  // namespace haptex::test
