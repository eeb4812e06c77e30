// The good files the pipeline makes pass every check (the mutation tests start from them).
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "qa/run_qa.hpp"
#include "tests/qa/qa_fixture.hpp"

namespace haptex::test {
namespace {

// Every check passes but `skipped` ones, which must say why they could not judge.
void expect_clean(const qa::Report& report, qa::FileKind kind, std::size_t checks, const std::set<std::string>& skipped = {}) {
  EXPECT_EQ(report.kind, kind);
  EXPECT_EQ(report.verdict(), "clean") << describe(report);
  EXPECT_EQ(report.checks.size(), checks);
  for (const auto& c : report.checks) {
    EXPECT_EQ(c.status, skipped.count(c.id) ? qa::Status::skip : qa::Status::pass) << c.id << ": " << c.message;
    std::cout << "    " << c.id << ": " << c.message << "\n";
  }
}

TEST(GoodFiles, RecordingsPassEveryCheck) {
  expect_clean(qa::run_qa({small_pipeline().recordings, {}}), qa::FileKind::recordings, 18);
}

// The synthetic gel's references are too smooth for gelsight.blur (docs/qa.md).
TEST(GoodFiles, GelsightPassesEveryCheck) {
  expect_clean(qa::run_qa({small_pipeline().gelsight, {}}), qa::FileKind::gelsight, 16, {"gelsight.blur"});
}

TEST(GoodFiles, DatasetWithItsSplitPassesEveryCheck) {
  expect_clean(qa::run_qa({small_pipeline().dataset, small_pipeline().split}), qa::FileKind::dataset, 5 + 13 + 11 + 2 + 9,
               {"gelsight.blur"});
}

TEST(GoodFiles, SplitManifestAloneFindsItsDataset) {
  expect_clean(qa::run_qa({small_pipeline().split, {}}), qa::FileKind::split, 9);
}

}  // namespace
}  // namespace haptex::test
