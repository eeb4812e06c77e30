#include "core/text/format.hpp"
#include "evaluate/report/paper_figures.hpp"

#include <cstdio>

namespace haptex::evaluate {
namespace {

std::string percent_text(double share) {
  return text::format("%.1f %%", 100 * share);
}

}  // namespace

double PaperFigure::better_share() const {
  return better ? double(*better) / double(materials) : better_percent.value_or(0) / 100;
}

double PaperFigure::significantly_better_share() const { return double(significantly_better) / double(materials); }

std::string PaperFigure::text() const {
  const std::string of = " of " + std::to_string(materials);
  if (!better) {
    return "better on " + text::format("%.2f %%", better_percent.value_or(0)) + ", significantly better on " + std::to_string(significantly_better) + of +
           " (" + percent_text(significantly_better_share()) + "), significantly worse on " +
           std::to_string(significantly_worse.value_or(0)) + " (" +
           percent_text(double(significantly_worse.value_or(0)) / double(materials)) + ")";
  }
  return "better on " + std::to_string(*better) + of + " (" + percent_text(better_share()) + "), significantly on " +
         std::to_string(significantly_better) + " (" + percent_text(significantly_better_share()) + ")";
}

std::optional<PaperFigure> paper_figure(std::string_view id) {
  const std::string_view base = id.substr(0, id.find(" ("));
  if (base == "per-material") return PaperFigure{93, 75, std::nullopt, 65, std::nullopt};
  if (base == "unified-new-actions") return PaperFigure{93, 82, std::nullopt, 78, std::nullopt};
  if (base == "unified-new-presses") return PaperFigure{93, 77, std::nullopt, 71, std::nullopt};
  if (base == "stitched-fgla" || base == "stitched-online" || base == "stitched-noise") return PaperFigure{93, std::nullopt, 86.02, 52, 2};
  return std::nullopt;
}

}  // namespace haptex::evaluate
