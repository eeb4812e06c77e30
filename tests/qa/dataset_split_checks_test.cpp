// The dataset and split checks fire, alone, on a copy of the good dataset file or split manifest
// with one defect. Manifest edits that move sections keep the rest of the manifest consistent: its
// window counts and coverage are recomputed with haptex split's own functions.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "qa/run_qa.hpp"
#include "dataset/window.hpp"
#include "split/coverage.hpp"
#include "split/dataset_view.hpp"
#include "split/sections.hpp"
#include "split/split_search.hpp"
#include "tests/support/mutations.hpp"
#include "tests/qa/qa_fixture.hpp"

namespace haptex::test {
namespace {

class DatasetMutation : public ::testing::Test {
 protected:
  qa::Report qa() const { return qa::run_qa({file_, {}}); }
  TempDir dir_;
  std::string file_ = copy_into(dir_, small_pipeline().dataset, "dataset.h5");
};

TEST_F(DatasetMutation, MissingSourceHashIsLayoutRequired) {
  Edit(file_).remove("@gelsight_sha256");
  expect_only(qa(), "layout.required");
}

TEST_F(DatasetMutation, MissingActionTableIsLayoutRequired) {
  Edit(file_).remove("windows/action");
  const qa::Report r = qa();
  expect_only(r, "layout.required");
  EXPECT_EQ(r.find("dataset.cache")->status, qa::Status::skip);
}

TEST_F(DatasetMutation, CopiedRecordingLayoutApplies) {
  Edit(file_).dataset("materials/woven_1/recordings/0/speed").set_attr("units", "m/s");
  expect_only(qa(), "layout.units");
}

TEST_F(DatasetMutation, StrideThatDoesNotMatchTheStartsIsDatasetWindows) {
  Edit(file_).group("windows").set_attr("stride", std::int64_t(50));
  const qa::Report r = qa();
  expect_only(r, "dataset.windows");
  EXPECT_NE(r.find("dataset.windows")->message.find("at stride 50 has"), std::string::npos) << r.find("dataset.windows")->message;
}

TEST_F(DatasetMutation, WindowOfAMissingRecordingIsDatasetWindows) {
  Edit(file_).change_floats("windows/recording", [](std::vector<float>& v) { v.back() = 3; });
  const qa::Report r = qa();
  expect_only(r, "dataset.windows");
  // The run it left is one window short, and the window itself names a recording that is not there.
  const auto& where = r.find("dataset.windows")->where;
  ASSERT_EQ(where.size(), 2u);
  EXPECT_NE(where[1].find("(woven_1, recording 3, start"), std::string::npos) << where[1];
}

TEST_F(DatasetMutation, StaleTargetIsDatasetCache) {
  Edit(file_).change_floats("windows/target", [](std::vector<float>& v) {
    for (std::size_t b = 0; b < 100; ++b) v[10 * 100 + b] *= 2;
  });
  const qa::Report r = qa();
  expect_only(r, "dataset.cache");
  EXPECT_EQ(r.find("dataset.cache")->where.size(), 1u);
  EXPECT_EQ(r.find("dataset.cache")->where[0].rfind("/windows[10] (", 0), 0u) << r.find("dataset.cache")->where[0];
}

TEST_F(DatasetMutation, ActionFromUnfilteredForceIsDatasetCache) {
  {
    Edit e(file_);
    // Every sandpaper window's force taken from the unfiltered signal.
    const auto raw = e.dataset("materials/sandpaper_1/recordings/0/force_normal").read<float>();
    const auto start = e.dataset("windows/start").read<std::int64_t>();
    const auto material = e.dataset("windows/material").read<std::int32_t>();
    const auto ids = e.dataset("windows/materials").read_strings();
    e.change_floats("windows/action", [&](std::vector<float>& v) {
      for (std::size_t w = 0; w < start.size(); ++w)
        if (ids[std::size_t(material[w])] == "sandpaper_1")
          for (std::size_t j = 0; j < 10; ++j) v[w * 20 + j] = raw[std::size_t(dataset::window_action_sample(start[w], j))];
    });
  }
  const qa::Report r = qa();
  expect_only(r, "dataset.cache");
  EXPECT_NE(r.find("dataset.cache")->message.find("force_normal_lp["), std::string::npos) << r.find("dataset.cache")->message;
}

class SplitMutation : public ::testing::Test {
 protected:
  qa::Report qa() const { return qa::run_qa({small_pipeline().dataset, manifest_}); }
  void edit(const std::function<void(nlohmann::json&)>& change) {
    nlohmann::json doc = read_json(manifest_);
    change(doc);
    write_json(manifest_, doc);
  }
  // New sections for material m, with its window counts and coverage recomputed as haptex split does.
  void resplit(nlohmann::json& doc, std::size_t m, const split::Sets& sets) {
    static const std::vector<split::MaterialWindows> windows = split::read_dataset_windows(small_pipeline().dataset);
    nlohmann::json& material = doc["materials"][m];
    const auto& w = *std::find_if(windows.begin(), windows.end(), [&](const auto& x) { return x.id == material["id"]; });
    const std::size_t sections = doc["parameters"]["sections"];
    std::array<std::vector<cv::Point2f>, 3> points;
    std::size_t crossing = 0;
    for (std::size_t i = 0; i < w.start.size(); ++i) {
      const std::int64_t t = w.start[i];
      const int s = split::section_of(dataset::window_first_sample(t), dataset::window_end_sample(t), w.recording_samples[std::size_t(w.recording[i])], sections);
      const int set = s < 0 ? -1 : split::set_of_section(sets, s);
      if (s < 0) ++crossing;
      else if (set >= 0) points[std::size_t(set)].emplace_back(w.speed[i], w.force[i]);
    }
    material["sections"] = {{"train", sets.train}, {"val", sets.val}, {"test", sets.test}};
    material["windows"] = {{"train", points[0].size()}, {"val", points[1].size()}, {"test", points[2].size()},
                           {"crossing", crossing}};
    material["coverage"] = {{"val", split::hull_coverage(points[0], points[1])},
                            {"test", split::hull_coverage(points[0], points[2])}};
    double worst = 1;
    for (const auto& x : doc["materials"]) worst = std::min({worst, x["coverage"]["val"].get<double>(), x["coverage"]["test"].get<double>()});
    doc["worst_coverage"] = worst;
  }
  TempDir dir_;
  std::string manifest_ = copy_into(dir_, small_pipeline().split, "split.json");
};

TEST_F(SplitMutation, TheManifestAloneIsCheckedWithTheDatasetItNames) {
  const qa::Report r = qa::run_qa({manifest_, {}});
  EXPECT_EQ(r.kind, qa::FileKind::split);
  EXPECT_EQ(r.verdict(), "clean") << describe(r);
  EXPECT_EQ(r.find("split.hashes")->status, qa::Status::pass);
}

TEST_F(SplitMutation, MissingDatasetSkipsWhatNeedsIt) {
  edit([](nlohmann::json& d) { d["dataset"]["path"] = "/nonexistent/dataset.h5"; });
  // Beside the manifest there is no d.h5 either.
  const qa::Report r = qa::run_qa({manifest_, {}});
  EXPECT_EQ(r.verdict(), "clean") << describe(r);
  EXPECT_EQ(r.find("split.hashes")->status, qa::Status::skip);
  EXPECT_NE(r.find("split.hashes")->message.find("was not found"), std::string::npos);
  EXPECT_EQ(r.find("split.sections")->status, qa::Status::pass);
}

TEST_F(SplitMutation, MissingFieldIsSplitSchema) {
  edit([](nlohmann::json& d) { d.erase("worst_coverage"); });
  const qa::Report r = qa();
  expect_only(r, "split.schema");
  EXPECT_EQ(r.find("split.sections")->status, qa::Status::skip);
}

TEST_F(SplitMutation, OtherDatasetHashIsSplitHashes) {
  edit([](nlohmann::json& d) { d["dataset"]["sha256"] = std::string(64, '0'); });
  expect_only(qa(), "split.hashes");
}

TEST_F(SplitMutation, OtherRecordingsHashIsSplitHashes) {
  edit([](nlohmann::json& d) { d["dataset"]["recordings_sha256"] = std::string(64, 'a'); });
  const qa::Report r = qa();
  expect_only(r, "split.hashes");
  EXPECT_EQ(r.find("split.hashes")->where, std::vector<std::string>{"#/dataset/recordings_sha256"});
}

TEST_F(SplitMutation, WrongRecordingCountIsSplitMaterials) {
  edit([](nlohmann::json& d) { d["materials"][0]["recordings"] = 2; });
  expect_only(qa(), "split.materials");
}

TEST_F(SplitMutation, MaterialMissingFromTheManifestIsSplitMaterials) {
  edit([](nlohmann::json& d) { d["materials"].erase(1); });
  const qa::Report r = qa();
  expect_only(r, "split.materials");
  EXPECT_NE(r.find("split.materials")->message.find("woven_1 has windows in the dataset but is not in the manifest"),
            std::string::npos);
}

TEST_F(SplitMutation, SectionInTwoSetsIsSplitSections) {
  edit([](nlohmann::json& d) { d["materials"][0]["sections"]["train"].push_back(d["materials"][0]["sections"]["val"][0]); });
  const qa::Report r = qa();
  expect_only(r, "split.sections");
  EXPECT_NE(r.find("split.sections")->message.find("is in both train and val"), std::string::npos);
}

TEST_F(SplitMutation, SectionOutOfRangeIsSplitSections) {
  edit([](nlohmann::json& d) { d["materials"][1]["sections"]["test"][0] = 25; });
  expect_only(qa(), "split.sections");
}

TEST_F(SplitMutation, MaterialWithoutValidationIsSplitSets) {
  edit([&](nlohmann::json& d) {
    split::Sets sets;
    sets.train = d["materials"][0]["sections"]["train"].get<std::vector<int>>();
    sets.test = d["materials"][0]["sections"]["test"].get<std::vector<int>>();
    const nlohmann::json coverage = d["materials"][0]["coverage"];
    resplit(d, 0, sets);  // the val sections belong to no set now
    d["materials"][0]["coverage"]["val"] = coverage["val"];
    d["worst_coverage"] = 1.0;
  });
  const qa::Report r = qa();
  expect_only(r, "split.sets");
  EXPECT_NE(r.find("split.sets")->message.find("nothing in val (0 sections, 0 windows)"), std::string::npos)
      << r.find("split.sets")->message;
}

TEST_F(SplitMutation, CrossingWindowsCountedInTrainingIsSplitCrossing) {
  edit([](nlohmann::json& d) {
    auto& w = d["materials"][0]["windows"];
    ASSERT_GT(w["crossing"].get<int>(), 0);
    w["train"] = w["train"].get<int>() + w["crossing"].get<int>();
    w["crossing"] = 0;
  });
  const qa::Report r = qa();
  expect_only(r, "split.crossing");
  EXPECT_NE(r.find("split.crossing")->message.find("cross a boundary"), std::string::npos);
}

TEST_F(SplitMutation, ValidationOutsideTheTrainingRangeIsSplitCoverage) {
  double val_coverage = 1;
  edit([&](nlohmann::json& d) {
    // Validation: the three sections with the fastest strokes, where training has nothing like them.
    const auto windows = split::read_dataset_windows(small_pipeline().dataset);
    const auto& w = windows.front();
    ASSERT_EQ(d["materials"][0]["id"], w.id);
    std::vector<double> speed(25, 0.0), count(25, 0.0);
    for (std::size_t i = 0; i < w.start.size(); ++i) {
      const int s = split::section_of(w.start[i] - 9, w.start[i] + 1000, w.recording_samples[0], 25);
      if (s >= 0) speed[std::size_t(s)] += w.speed[i], count[std::size_t(s)] += 1;
    }
    std::vector<int> order(25);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return speed[a] / std::max(1.0, count[a]) > speed[b] / std::max(1.0, count[b]); });
    split::Sets sets;
    sets.val = {order[0], order[1], order[2]};
    sets.test = {order[3], order[4], order[5]};
    for (int s = 6; s < 25; ++s) sets.train.push_back(order[std::size_t(s)]);
    for (auto* set : {&sets.train, &sets.val, &sets.test}) std::sort(set->begin(), set->end());
    resplit(d, 0, sets);
    val_coverage = d["materials"][0]["coverage"]["val"];
  });
  ASSERT_LT(val_coverage, 0.9) << "the fastest sections should lie outside the training hull";
  const qa::Report r = qa();
  expect_only(r, "split.coverage");
  EXPECT_NE(r.find("split.coverage")->message.find("under min_coverage 90%"), std::string::npos) << r.find("split.coverage")->message;
}

TEST_F(SplitMutation, CoverageThatWasNotMeasuredIsSplitCoverageRecorded) {
  edit([](nlohmann::json& d) { d["materials"][1]["coverage"]["test"] = 0.5; });  // worst_coverage now disagrees too
  const qa::Report r = qa();
  expect_only(r, "split.coverage_recorded");
  EXPECT_EQ(r.find("split.coverage_recorded")->severity, qa::Severity::warning);
  EXPECT_EQ(r.find("split.coverage_recorded")->where.size(), 2u);
}

TEST_F(SplitMutation, TwoTrainingPressesAreSplitPresses) {
  edit([](nlohmann::json& d) { d["materials"][0]["presses"]["train"].erase(2); });
  const qa::Report r = qa();
  expect_only(r, "split.presses");
  EXPECT_NE(r.find("split.presses")->message.find("2 train presses"), std::string::npos);
}

TEST_F(SplitMutation, PressInTwoSetsIsSplitPresses) {
  edit([](nlohmann::json& d) { d["materials"][0]["presses"]["train"].push_back(d["materials"][0]["presses"]["val"][0]); });
  const qa::Report r = qa();
  expect_only(r, "split.presses");
  EXPECT_NE(r.find("split.presses")->message.find("is in two sets"), std::string::npos) << r.find("split.presses")->message;
}

TEST_F(SplitMutation, PressMissingFromTheDatasetIsSplitPresses) {
  edit([](nlohmann::json& d) { d["materials"][1]["presses"]["test"][0] = 7; });
  const qa::Report r = qa();
  expect_only(r, "split.presses");
  EXPECT_NE(r.find("split.presses")->message.find("press 7 is not in the dataset"), std::string::npos);
}

TEST_F(SplitMutation, SplitOfAnotherDatasetFailsOnlyItsHashWhenTheTableMatches) {
  // A dataset rebuilt from the same inputs differs in bytes (created_utc), not in windows.
  TempDir other;
  const std::string copy = copy_into(other, small_pipeline().dataset, "d.h5");
  Edit(copy).root().set_attr("created_utc", "2000-01-01T00:00:00Z");
  expect_only(qa::run_qa({copy, manifest_}), "split.hashes");
}

}  // namespace
}  // namespace haptex::test
