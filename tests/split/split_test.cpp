#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>

#include "dataset/window.hpp"
#include "core/error.hpp"
#include "core/json/schema.hpp"
#include "split/coverage.hpp"
#include "split/dataset_view.hpp"
#include "split/sections.hpp"
#include "split/split_manifest.hpp"
#include "split/split_search.hpp"
#include "tests/support/pipeline_fixture.hpp"

namespace haptex::split {
namespace {

TEST(Sections, WindowsBelongOnlyToTheSectionHoldingAllTheirSamples) {
  // 1000 samples in 4 sections: [0,250) [250,500) [500,750) [750,1000).
  EXPECT_EQ(section_begin(1, 1000, 4), 250);
  EXPECT_EQ(section_of(0, 250, 1000, 4), 0);
  EXPECT_EQ(section_of(250, 500, 1000, 4), 1);
  EXPECT_EQ(section_of(249, 300, 1000, 4), -1);
  EXPECT_EQ(section_of(700, 751, 1000, 4), -1);
  EXPECT_EQ(section_of(900, 1001, 1000, 4), -1);
  // Uneven lengths: 1003 samples in 25 sections, every sample in exactly one section.
  for (std::int64_t t = 0; t < 1003; ++t) {
    const int s = section_of(t, t + 1, 1003, 25);
    ASSERT_GE(s, 0);
    EXPECT_GE(t, section_begin(std::size_t(s), 1003, 25));
    EXPECT_LT(t, section_begin(std::size_t(s) + 1, 1003, 25));
  }
}

TEST(Coverage, ShareOfPointsInsideTheTrainingHull) {
  const std::vector<cv::Point2f> square = {{0, 0}, {10, 0}, {10, 1}, {0, 1}, {5, 0.5f}};
  EXPECT_DOUBLE_EQ(hull_coverage(square, {{5, 0.5f}, {10, 1}, {11, 0.5f}, {5, 2}}), 0.5);
  EXPECT_DOUBLE_EQ(hull_coverage({{0, 0}, {1, 1}}, {{0.5f, 0.5f}}), 0.0);  // no area
  EXPECT_DOUBLE_EQ(hull_coverage(square, {}), 1.0);
}

// One material whose force and speed wander over the same range in every section; or, as a ring,
// whose every section holds its own arc of a circle in the (speed, force) plane, so no section is
// inside the hull of the others.
MaterialWindows wandering(const std::string& id, bool ring = false) {
  MaterialWindows m;
  m.id = m.name = id;
  m.recording_samples = {100000, 100000};
  m.presses = 5;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<float> unit(0, 1);
  for (int r = 0; r < 2; ++r)
    for (std::int64_t t : dataset::window_starts(100000, 100)) {
      m.recording.push_back(r);
      m.start.push_back(t);
      const float angle = 2 * float(M_PI) * float(t) / 100000.0f;
      m.speed.push_back(ring ? 100 + 50 * std::cos(angle) : 200 * unit(rng));
      m.force.push_back(ring ? 2 + std::sin(angle) : 4 * unit(rng));
    }
  return m;
}

TEST(SplitSearch, SetsAreDisjointCoveredAndSeeded) {
  const std::vector<MaterialWindows> materials = {wandering("book"), wandering("cork")};
  const auto a = search_split(materials, {}, "dataset.h5"), b = search_split(materials, {}, "dataset.h5");
  ASSERT_EQ(a.size(), 2u);
  for (const MaterialSplit& s : a) {
    std::set<int> all;
    for (const auto* set : {&s.sections.train, &s.sections.val, &s.sections.test})
      for (int k : *set) EXPECT_TRUE(all.insert(k).second) << "section " << k << " in two sets";
    EXPECT_EQ(all.size(), 25u);
    EXPECT_EQ(s.sections.val.size(), 3u);
    EXPECT_EQ(s.sections.test.size(), 3u);
    EXPECT_GE(s.worst(), 0.9);
    EXPECT_EQ(s.presses.train.size(), 3u);
    EXPECT_EQ(s.presses.val.size(), 1u);
    EXPECT_EQ(s.presses.test.size(), 1u);
    // Sections are 4000 samples here: a window crosses one when its first and last samples differ in t / 4000.
    std::size_t crossing = 0;
    for (std::int64_t t : materials[0].start) crossing += dataset::window_first_sample(t) / 4000 != (dataset::window_end_sample(t) - 1) / 4000;
    EXPECT_EQ(s.train_windows + s.val_windows + s.test_windows + s.crossing_windows, materials[0].start.size());
    EXPECT_EQ(s.crossing_windows, crossing);
  }
  EXPECT_EQ(a[0].sections.val, b[0].sections.val);
  SplitOptions other;
  other.seed = 1;
  EXPECT_NE(search_split(materials, other, "dataset.h5")[0].sections.train, a[0].sections.train);
  EXPECT_NE(a[0].sections.val, a[1].sections.val);  // materials draw independently
}

TEST(SplitSearch, FailsNamingMaterialsBelowTheCoverageThreshold) {
  const std::vector<MaterialWindows> materials = {wandering("book"), wandering("cork_ring", true)};
  try {
    search_split(materials, {}, "dataset.h5");
    FAIL() << "a drifting material reached the coverage threshold";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::failed);
    const std::string message = e.what();
    EXPECT_NE(message.find("cork_ring (val"), std::string::npos) << message;
    EXPECT_EQ(message.find("book"), std::string::npos) << message;
    EXPECT_NE(message.find("--tries"), std::string::npos) << message;
  }
  SplitOptions lenient;
  lenient.min_coverage = 0.0;
  EXPECT_NO_THROW(search_split(materials, lenient, "dataset.h5"));
}

TEST(SplitSearch, RefusesTooFewPressesAndImpossibleSections) {
  MaterialWindows m = wandering("book");
  m.presses = 4;
  EXPECT_THROW(search_split({m}, {}, "dataset.h5"), Error);
  SplitOptions bad;
  bad.sections = 6;
  bad.val = 3;
  bad.test = 3;
  EXPECT_THROW(search_split({wandering("book")}, bad, "dataset.h5"), Error);
}

TEST(SplitManifest, FollowsItsSchemaAndRecordsTheInputsHashes) {
  test::PipelineFiles files;
  test::make_pipeline_dataset(files, {3.0, 0});
  const auto windows = read_dataset_windows(files.dataset);
  ASSERT_EQ(windows.size(), 2u);
  SplitOptions o;
  o.min_coverage = 0;  // the sample recordings' force and speed are smooth sines, not strokes
  const auto splits = search_split(windows, o, "dataset.h5");
  const nlohmann::json doc = manifest_json(files.dataset, o, splits, "test");
  EXPECT_NO_THROW(json::validate(doc, "split.schema.json", "manifest"));
  EXPECT_EQ(doc["dataset"]["sha256"].get<std::string>().size(), 64u);
  EXPECT_EQ(doc["materials"][0]["id"], "book");
  EXPECT_EQ(doc["materials"][0]["recordings"], 2);
}

}  // namespace
}  // namespace haptex::split
