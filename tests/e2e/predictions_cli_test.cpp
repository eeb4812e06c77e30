// haptex evaluate --predictions (docs/benchmark.md): a model trained outside haptex, scored on the
// grid of haptex windows beside the built-in models. The perfect predictor (the recorded spectra
// and signals themselves) must score 0 on every window, which holds only when rows and samples line
// up with the windows exactly as evaluate scores them. The kNN example: tests/e2e/windows_cli_test.cpp.
// Refusals: tests/hostile/predictions_refusals_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <nlohmann/json.hpp>

#include "core/json/schema.hpp"
#include "core/sha256.hpp"
#include "tests/support/predictions_files.hpp"
#include "tests/support/quick_models.hpp"
#include "tests/support/run_haptex.hpp"
#include "tests/support/small_pipeline.hpp"

namespace haptex::test {
namespace {

const nlohmann::json& experiment(const nlohmann::json& results, const std::string& id) {
  for (const auto& e : results["experiments"])
    if (e["id"] == id) return e;
  static const nlohmann::json none;
  ADD_FAILURE() << id << " missing";
  return none;
}

// The cells of a CSV file without quoted fields, row by row.
std::vector<std::vector<std::string>> read_csv(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::stringstream fields(line);
    for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

struct Evaluated {
  nlohmann::json results;
  std::string out;
};

Evaluated evaluate(const TempDir& dir, const std::vector<std::string>& extra, const std::string& report) {
  const SmallPipeline& p = small_pipeline();
  std::vector<std::string> args{"evaluate", p.dataset, "--split", p.split, "--repeats", "2", "--truth", p.truth, "-o", dir.file(report), "--json"};
  args.insert(args.end(), extra.begin(), extra.end());
  const CommandResult r = run_haptex(args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return {r.exit_code == 0 ? nlohmann::json::parse(r.out) : nlohmann::json{}, r.out};
}

GridTable grid(const TempDir& dir) {
  const SmallPipeline& p = small_pipeline();
  const CommandResult r = run_haptex({"windows", p.dataset, "--split", p.split, "-o", dir.file("windows.h5")});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return read_grid(dir.file("windows.h5"));
}

TEST(PredictionsCli, TheRecordingItselfScoresZeroBesideTheBuiltInModels) {
  const TempDir dir;
  const GridTable g = grid(dir);
  const std::string file = dir.file("perfect.h5");
  write_predictions(file, perfect_predictions(g, small_pipeline().dataset));
  const Evaluated e = evaluate(dir, {"--model", quick_model(false), "--predictions", "perfect=" + file}, "report");
  const nlohmann::json& r = e.results;
  EXPECT_NO_THROW(json::validate(r, "results.schema.json", "results.json"));
  ASSERT_EQ(r["inputs"]["predictions"].size(), 1u);
  EXPECT_EQ(r["inputs"]["predictions"][0]["sha256"], sha256_file(file));
  EXPECT_EQ(r["inputs"]["predictions"][0]["name"], "perfect");
  for (const char* id : {"external-perfect", "stitched-external-perfect"}) {
    const nlohmann::json& x = experiment(r, id);
    ASSERT_EQ(x["materials"].size(), 2u) << id;
    std::size_t windows = 0;
    for (const auto& m : x["materials"]) {
      windows += m["windows"].get<std::size_t>();
      EXPECT_LT(m["model"].get<double>(), 1e-5 * m["baseline"].get<double>()) << id << " " << m["id"];
      // Far below the oracle (which the report flags as a broken oracle once the grid has windows enough to tell).
      EXPECT_LT(m["floor_ratio"].get<double>(), 1e-4) << id << " " << m["id"];
    }
    EXPECT_EQ(windows, g.rows()) << id;
  }
  // The built-in model's experiments are still there, unchanged in kind.
  EXPECT_EQ(experiment(r, "unified-new-actions")["materials"].size(), 2u);
  // Its compute times give it points in the speed chart: 1e-4 s per 10 ms window.
  std::map<std::string, const nlohmann::json*> speed;
  for (const auto& point : r["speed"]) speed[point["method"]] = &point;
  ASSERT_TRUE(speed.count("perfect (external)"));
  EXPECT_NEAR((*speed["perfect (external)"])["seconds_per_second"].get<double>(), 0.01, 1e-9);
  ASSERT_TRUE(speed.count("perfect (external, signal)"));
  const auto realism = std::find_if(r["realism"].begin(), r["realism"].end(), [](const auto& x) { return x["method"] == "perfect (external, signal)"; });
  ASSERT_NE(realism, r["realism"].end());
  for (const auto& m : (*realism)["materials"]) EXPECT_NEAR(m["spread_ratio"].get<double>(), 1.0, 1e-4) << m["id"];
  // Fig. 5's examples draw it beside the recording: the same window's spectrum, the same section's signal.
  ASSERT_FALSE(r["examples"].empty());
  for (const auto& x : r["examples"])
    for (const char* csv : {"spectra_csv", "signals_csv"}) {
      const auto rows = read_csv(dir.file("report/" + x[csv].get<std::string>()));
      ASSERT_GT(rows.size(), 2u);
      ASSERT_EQ(rows[0].back(), "external-perfect") << csv;
      for (std::size_t i = 1; i < rows.size(); ++i)
        EXPECT_NEAR(std::stod(rows[i].back()), std::stod(rows[i][1]), 1e-5 * (1 + std::abs(std::stod(rows[i][1])))) << csv << " row " << i;
    }
}

// Off by one sample, or rows of another material: no longer zero. What makes the test above able to fail.
TEST(PredictionsCli, MisalignedPredictionsDoNotScoreZero) {
  const TempDir dir;
  const GridTable g = grid(dir);
  Predictions p = perfect_predictions(g, small_pipeline().dataset);
  for (auto& signal : p.signals) std::rotate(signal.begin(), signal.begin() + 1, signal.end());
  std::reverse(p.spectra.begin(), p.spectra.end());  // rows and bins reversed
  p.query_seconds.reset();
  write_predictions(dir.file("shifted.h5"), p);
  const Evaluated e = evaluate(dir, {"--predictions", "shifted=" + dir.file("shifted.h5"), "--reconstruct", "none"}, "report");
  for (const char* id : {"external-shifted", "stitched-external-shifted"})
    for (const auto& m : experiment(e.results, id)["materials"])
      EXPECT_GT(m["model"].get<double>(), 0.01 * m["baseline"].get<double>()) << id << " " << m["id"];
  // Without a built-in model: no latent map; without /@query_seconds: no speed point for the spectra. Notes say both.
  EXPECT_TRUE(e.results["latents"].empty());
  for (const auto& point : e.results["speed"]) EXPECT_NE(point["method"], "shifted (external)");
  const std::string notes = e.results["notes"].dump();
  EXPECT_NE(notes.find("no unified model"), std::string::npos) << notes;
  EXPECT_NE(notes.find("gives no /@query_seconds"), std::string::npos) << notes;
}

}  // namespace
}  // namespace haptex::test
