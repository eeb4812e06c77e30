// evaluate/report/paper_figures.hpp pins the paper's numbers (Heravi et al., ICRA 2020) to the experiments
// haptex repeats, and to nothing else.
#include "evaluate/report/paper_figures.hpp"

#include <gtest/gtest.h>

namespace haptex::evaluate {
namespace {

TEST(PaperFigures, EachRepeatedExperimentHasThePapersCounts) {
  struct Row {
    const char* id;
    std::optional<std::size_t> better;
    std::size_t significantly_better;
  };
  for (const Row& row : {Row{"per-material", 75, 65}, Row{"unified-new-actions", 82, 78}, Row{"unified-new-presses", 77, 71},
                         Row{"unified-new-actions (model.h5)", 82, 78}}) {
    const auto paper = paper_figure(row.id);
    ASSERT_TRUE(paper.has_value()) << row.id;
    EXPECT_EQ(paper->materials, 93u);
    EXPECT_EQ(paper->better, row.better) << row.id;
    EXPECT_EQ(paper->significantly_better, row.significantly_better) << row.id;
    EXPECT_FALSE(paper->significantly_worse.has_value()) << row.id;
  }
  for (const char* id : {"stitched-fgla", "stitched-online"}) {
    const auto paper = paper_figure(id);
    ASSERT_TRUE(paper.has_value()) << id;
    EXPECT_FALSE(paper->better.has_value());
    EXPECT_EQ(paper->better_percent, 86.02);
    EXPECT_EQ(paper->significantly_better, 52u);
    EXPECT_EQ(paper->significantly_worse, 2u);
  }
}

TEST(PaperFigures, HaptexsOwnComparisonsQuoteNothing) {
  for (const char* id : {"unified-new-actions-vs-mean-spectrum", "per-material-vs-mean-spectrum (a.h5)", "mean-spectrum", ""})
    EXPECT_FALSE(paper_figure(id).has_value()) << id;
}

TEST(PaperFigures, TheTextComputesTheShares) {
  EXPECT_EQ(paper_figure("unified-new-actions")->text(), "better on 82 of 93 (88.2 %), significantly on 78 (83.9 %)");
  EXPECT_EQ(paper_figure("stitched-fgla")->text(),
            "better on 86.02 %, significantly better on 52 of 93 (55.9 %), significantly worse on 2 (2.2 %)");
  EXPECT_NEAR(paper_figure("stitched-fgla")->better_share(), 0.8602, 1e-12);
}

}  // namespace
}  // namespace haptex::evaluate
