#pragma once
// What Heravi et al. (ICRA 2020) report for the experiments haptex repeats, quoted exactly: the only
// paper numbers a report may show. Counts are over the paper's 93 materials; the stitched row gives
// its "better" share as a percentage (86.02 %), not a count.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace haptex::evaluate {

struct PaperFigure {
  std::size_t materials = 93;
  std::optional<std::size_t> better;     // a count, where the paper gives one
  std::optional<double> better_percent;  // the stitched row's 86.02 %, as the paper writes it
  std::size_t significantly_better = 0;
  std::optional<std::size_t> significantly_worse;  // the stitched row only

  double better_share() const;  // of the materials
  double significantly_better_share() const;
  // "better on 82 of 93 (88.2 %), significantly on 78 (83.9 %)"; the stitched row: "better on 86.02 %,
  // significantly better on 52 of 93 (55.9 %), significantly worse on 2 (2.2 %)"
  std::string text() const;
};

// The experiment ids of run_evaluation (per-material, unified-new-actions, unified-new-presses,
// stitched-fgla, stitched-online), with or without a " (model label)" suffix; nullopt for every other
// comparison (the mean-spectrum ones are haptex's own).
std::optional<PaperFigure> paper_figure(std::string_view experiment_id);

}  // namespace haptex::evaluate
