// haptex windows as a user runs it on the small pipeline, then python/'s kNN example on its grid,
// both checked with h5py (tests/e2e/check_windows.py). Its refusals: tests/hostile/windows_refusals_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>

#include "core/sha256.hpp"
#include "core/temporary_name.hpp"
#include "tests/support/quick_models.hpp"
#include "tests/support/run_haptex.hpp"
#include "tests/support/small_pipeline.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {
namespace fs = std::filesystem;

const std::string kSource = std::string(HAPTEX_SCHEMA_DIR) + "/../";

TEST(WindowsCli, WritesTheEvaluationGridThatTheKnnExamplePredicts) {
  if (!python_has("h5py, numpy")) GTEST_SKIP() << "python3-h5py is not installed (make deps installs it)";
  const TempDir dir;
  const SmallPipeline& p = small_pipeline();
  const std::string windows = dir.file("windows.h5"), preds = dir.file("preds.h5");
  const CommandResult r = run_haptex({"windows", p.dataset, "--split", p.split, "-o", windows, "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json printed = nlohmann::json::parse(r.out);
  EXPECT_GT(printed["windows"].get<int>(), 0);
  EXPECT_EQ(printed["materials"], 2);
  EXPECT_EQ(printed["split_sha256"], sha256_file(p.split));

  const CommandResult layout = run_python({kSource + "tests/e2e/check_layout.py", kSource + "schemas/hdf5-layout.md", windows, "Windows file"});
  EXPECT_EQ(layout.exit_code, 0) << layout.out << layout.err;
  const CommandResult knn = run_python({kSource + "python/examples/knn_baseline.py", p.dataset, p.split, windows, "-o", preds});
  ASSERT_EQ(knn.exit_code, 0) << knn.out << knn.err;
  EXPECT_TRUE(temporaries_of(preds).empty());
  const CommandResult checked = run_python({kSource + "tests/e2e/check_windows.py", kSource + "python", p.dataset, p.split, windows, preds});
  EXPECT_EQ(checked.exit_code, 0) << checked.out << checked.err;
  EXPECT_NE(checked.out.find("windows ok"), std::string::npos) << checked.out;

  // The predictions appear in haptex evaluate's report beside the built-in model (docs/benchmark.md).
  const CommandResult e = run_haptex({"evaluate", p.dataset, "--split", p.split, "--model", quick_model(false), "--predictions",
                                      "knn=" + preds, "--repeats", "2", "--reconstruct", "none", "-o", dir.file("report"), "--json"});
  ASSERT_EQ(e.exit_code, 0) << e.err;
  const nlohmann::json results = nlohmann::json::parse(e.out);
  std::set<std::string> ids;
  for (const auto& x : results["experiments"]) {
    ids.insert(x["id"]);
    if (x["id"] == "external-knn") {
      EXPECT_EQ(x["materials"].size(), 2u);
    }
  }
  for (const char* id : {"unified-new-actions", "external-knn", "external-knn-vs-mean-spectrum", "external-knn-vs-expected-ar"})
    EXPECT_TRUE(ids.count(id)) << id;
  EXPECT_NE(results["inputs"]["predictions"][0]["source"].get<std::string>().find("knn_baseline.py"), std::string::npos);
  const auto point = std::find_if(results["speed"].begin(), results["speed"].end(), [](const auto& x) { return x["method"] == "knn (external)"; });
  ASSERT_NE(point, results["speed"].end()) << "the example times its queries";
  EXPECT_GT((*point)["seconds_per_second"].get<double>(), 0.0);
  const CommandResult preds_layout =
      run_python({kSource + "tests/e2e/check_layout.py", kSource + "schemas/hdf5-layout.md", preds, "Predictions file", "--own"});
  EXPECT_EQ(preds_layout.exit_code, 0) << preds_layout.out << preds_layout.err;
}

// The PyTorch example where python3-torch is installed (make bench installs it): it learns (its best
// epoch's training loss is below its first's) and evaluate scores its predictions.
TEST(WindowsCli, TheTorchExampleLearnsAndItsPredictionsAreScored) {
  if (!python_has("h5py, numpy, torch")) GTEST_SKIP() << "python3-torch is not installed (make bench installs it)";
  const TempDir dir;
  const SmallPipeline& p = small_pipeline();
  const std::string windows = dir.file("windows.h5"), preds = dir.file("mlp.h5");
  ASSERT_EQ(run_haptex({"windows", p.dataset, "--split", p.split, "-o", windows}).exit_code, 0);
  const CommandResult mlp = run_python({kSource + "python/examples/torch_mlp.py", p.dataset, p.split, windows, "-o", preds, "--epochs", "30"});
  ASSERT_EQ(mlp.exit_code, 0) << mlp.out << mlp.err;
  double first = 0, first_val = 0, best = 0, best_val = 0;
  int epoch = 0;
  ASSERT_EQ(std::sscanf(mlp.out.c_str(), "losses (training, validation): epoch 1 %lf %lf; best epoch %d %lf %lf", &first, &first_val, &epoch,
                        &best, &best_val), 5) << mlp.out;
  EXPECT_LT(best, first) << mlp.out;
  const CommandResult e = run_haptex({"evaluate", p.dataset, "--split", p.split, "--predictions", "mlp=" + preds, "--repeats", "2",
                                      "--reconstruct", "none", "-o", dir.file("report"), "--json"});
  ASSERT_EQ(e.exit_code, 0) << e.err;
  const nlohmann::json results = nlohmann::json::parse(e.out);
  EXPECT_EQ(results["experiments"][0]["id"], "external-mlp");
  EXPECT_EQ(results["experiments"][0]["materials"].size(), 2u);
}

}  // namespace
}  // namespace haptex::test
