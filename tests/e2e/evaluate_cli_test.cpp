// haptex evaluate as a user runs it, on the small pipeline's dataset, split and a quickly trained model.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <nlohmann/json.hpp>

#include "core/json/schema.hpp"
#include "core/temporary_name.hpp"
#include "dataset/format.hpp"
#include "dataset/window_table.hpp"
#include "tests/support/quick_models.hpp"
#include "tests/support/run_haptex.hpp"
#include "tests/support/small_pipeline.hpp"

namespace haptex::test {
namespace {
namespace fs = std::filesystem;

struct Models {
  std::string unified = quick_model(false), per_material = quick_model(true);
};

const Models& models() {
  static const Models m;
  return m;
}

TEST(EvaluateCli, WritesAReportWhoseTotalsMatchItsTables) {
  const TempDir dir;
  const SmallPipeline& p = small_pipeline();
  const CommandResult r = run_haptex({"evaluate", p.dataset, "--split", p.split, "--model", models().unified, "--model",
                                      models().per_material, "--repeats", "3", "-o", dir.file("report"), "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json printed = nlohmann::json::parse(r.out);
  const nlohmann::json results = json::read_file(dir.file("report/results.json"));
  EXPECT_EQ(printed, results);
  EXPECT_NO_THROW(json::validate(results, "results.schema.json", "results.json"));
  std::set<std::string> ids;
  for (const auto& e : results["experiments"]) {
    ids.insert(e["id"]);
    // The totals are counts over the per-material rows.
    std::size_t better = 0;
    for (const auto& m : e["materials"]) better += m["better"].get<bool>() ? 1 : 0;
    EXPECT_EQ(e["totals"]["better"], better) << e["id"];
    EXPECT_EQ(e["materials"].size(), 2u);
  }
  for (const char* id : {"per-material", "unified-new-actions", "unified-new-presses", "stitched-fgla"})
    EXPECT_TRUE(ids.count(id)) << id << " missing";
  std::ifstream report(dir.file("report/report.md"));
  const std::string text{std::istreambuf_iterator<char>(report), {}};
  EXPECT_NE(text.find("better on"), std::string::npos);
  EXPECT_TRUE(temporaries_of(dir.file("report")).empty());
}

// haptex windows writes the windows evaluate scores (docs/windows.md): per material as many as it
// scored, read through the dataset's own /windows reader since the layouts agree.
TEST(EvaluateCli, ScoresAsManyWindowsPerMaterialAsHaptexWindowsWrites) {
  const TempDir dir;
  const SmallPipeline& p = small_pipeline();
  const CommandResult r = run_haptex({"evaluate", p.dataset, "--split", p.split, "--model", models().per_material, "--repeats", "2",
                                      "--reconstruct", "none", "-o", dir.file("report"), "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_EQ(run_haptex({"windows", p.dataset, "--split", p.split, "-o", dir.file("windows.h5")}).exit_code, 0);
  const dataset::WindowTable grid = dataset::read_window_table(dataset::open_checked(dir.file("windows.h5"), dataset::Kind::windows));
  std::map<std::string, std::size_t> written;
  for (std::int32_t m : grid.material) ++written[grid.materials.at(std::size_t(m))];
  const nlohmann::json results = nlohmann::json::parse(r.out);
  ASSERT_FALSE(results["experiments"].empty());
  for (const auto& e : results["experiments"]) {
    ASSERT_EQ(e["materials"].size(), written.size()) << e["id"];
    for (const auto& m : e["materials"]) EXPECT_EQ(m["windows"].get<std::size_t>(), written[m["id"].get<std::string>()]) << e["id"] << " " << m["id"];
  }
}

// synth materials' truth.h5 knows what generated every recording: the floor is the oracle, and no
// model beats it beyond sampling error.
TEST(EvaluateCli, WithTheTruthTheFloorIsTheOracle) {
  const TempDir dir;
  const SmallPipeline& p = small_pipeline();
  const CommandResult r = run_haptex({"evaluate", p.dataset, "--split", p.split, "--model", models().unified, "--model",
                                      models().per_material, "--repeats", "3", "--truth", p.truth, "-o", dir.file("report"), "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json results = nlohmann::json::parse(r.out);
  EXPECT_EQ(results["floor_kind"], "oracle");
  ASSERT_EQ(results["floors"].size(), 2u);
  for (const auto& f : results["floors"]) {
    EXPECT_EQ(f["kind"], "oracle");
    EXPECT_EQ(f["method"], "truth grid");
    EXPECT_GT(f["distance"].get<double>(), 0.0);
    // Knowing only the action at each window's middle cannot beat knowing the whole window's.
    EXPECT_GE(f["input_floor"].get<double>(), 0.99 * f["distance"].get<double>()) << f["id"];
  }
  std::set<std::string> ids;
  for (const auto& e : results["experiments"]) {
    ids.insert(e["id"]);
    for (const auto& m : e["materials"]) {
      EXPECT_FALSE(m["below_floor"].get<bool>()) << e["id"] << " " << m["id"] << ": a model beats the oracle";
      EXPECT_GT(m["floor"].get<double>(), 0.0);
      EXPECT_GT(m["model_lsd_db"].get<double>(), 0.0);
    }
  }
  for (const char* id : {"per-material-vs-expected-ar", "unified-new-actions-vs-expected-ar", "unified-new-presses-vs-mean-spectrum"})
    EXPECT_TRUE(ids.count(id)) << id << " missing";
  EXPECT_FALSE(results["realism"].empty());
}

// A --truth that is not a truth file (here the dataset itself, under a name with quotes and a
// back-quote) is refused before anything is written, naming the file and the attribute.
TEST(EvaluateCli, RefusesATruthThatIsNotOne) {
  const TempDir dir;
  const SmallPipeline& p = small_pipeline();
  const std::string fake = copy_into(dir, p.dataset, "tru'th \"`x`\".h5");
  const CommandResult r = run_haptex({"evaluate", p.dataset, "--split", p.split, "--model", models().unified, "--truth", fake, "-o",
                                      dir.file("report")});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(fake), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("not a truth file (truth/2)"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.file("report")));
  EXPECT_TRUE(temporaries_of(dir.file("report")).empty());
}

TEST(EvaluateCli, RefusesAModelTrainedOnAnotherSplit) {
  const TempDir dir;
  const SmallPipeline& p = small_pipeline();
  // The same dataset, cut with another seed: other test sections, which the model may have trained on.
  const CommandResult split = run_haptex({"split", p.dataset, "-o", dir.file("other.json"), "--seed", "99", "--no-plots"});
  ASSERT_EQ(split.exit_code, 0) << split.err;
  const CommandResult r = run_haptex({"evaluate", p.dataset, "--split", dir.file("other.json"), "--model", models().unified, "-o",
                                      dir.file("report")});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(models().unified), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("another dataset or split"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.file("report")));
}

TEST(EvaluateCli, PublishedBaselineNeedsItsFolderAndAMatchingModelFile) {
  const TempDir dir;
  const SmallPipeline& p = small_pipeline();
  const CommandResult missing = run_haptex({"evaluate", p.dataset, "--split", p.split, "--model", models().unified, "--baseline",
                                            "hatt-published", "-o", dir.file("report")});
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("--hatt-models"), std::string::npos) << missing.err;
  fs::create_directories(dir.file("models"));
  const CommandResult none = run_haptex({"evaluate", p.dataset, "--split", p.split, "--model", models().unified, "--baseline",
                                         "hatt-published", "--hatt-models", dir.file("models"), "-o", dir.file("report")});
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_NE(none.err.find(dir.file("models")), std::string::npos) << none.err;
  EXPECT_FALSE(fs::exists(dir.file("report")));
  EXPECT_TRUE(temporaries_of(dir.file("report")).empty());
  // Review 5: --hatt-models without that baseline was passed over, and the report compared with the refit.
  const CommandResult unread = run_haptex({"evaluate", p.dataset, "--split", p.split, "--model", models().unified,
                                           "--hatt-models", dir.file("models"), "-o", dir.file("report")});
  EXPECT_EQ(unread.exit_code, 2);
  EXPECT_NE(unread.err.find("--baseline hatt-published"), std::string::npos) << unread.err;
  EXPECT_FALSE(fs::exists(dir.file("report")));
}

}  // namespace
}  // namespace haptex::test
