#pragma once
// An evaluation as JSON: results.json of the report, schemas/results.schema.json; and the figures
// every report writer derives from an evaluation the same way (report.md, results.json, the CSVs).
//
// JSON has no infinities or NaN. Every floating-point value is a number when finite and otherwise
// one of the strings "inf", "-inf" or "nan" (so t = -infinity, which Welch's test gives for two
// samples without spread, keeps its sign; see evaluate/welch_test.hpp), except a figure that was not
// measured (kNotMeasured: the log-spectral distances, floors, mean spectra, realism), which is null.
#include <nlohmann/json.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "evaluate/evaluation_results.hpp"
#include "evaluate/report_csv.hpp"

namespace haptex::evaluate {

inline constexpr double kSignificanceLevel = 0.05;  // MaterialComparison::significant(): Welch, two-sided

// A double as JSON: the number, or "inf", "-inf", "nan".
nlohmann::json json_number(double x);
// A figure that may not have been measured: null for NaN, otherwise json_number.
nlohmann::json json_measured(double x);

// The whole evaluation, stamped with haptex's version and created_utc, naming each part's CSV file
// (layout); examples by name and size only, their data is in their CSVs. Follows
// schemas/results.schema.json.
nlohmann::json results_json(const Evaluation& e, const ReportLayout& layout, const std::string& created_utc);

// --- Figures derived from an evaluation, shared by the writers ------------------------------------

// Which question an experiment answers, by its id without the " (model label)" suffix
// (docs/evaluate.md, "Which comparison answers which question"):
// - rendered_ar: predicted spectra against the AR baseline rendered (per-material, unified-new-*: the paper's protocol);
// - expected_ar: predicted spectra against the AR baseline's expected spectrum (*-vs-expected-ar: like for like);
// - mean_spectrum: predicted spectra against each material's mean training spectrum (*-vs-mean-spectrum);
// - stitched: the stitched signal against the AR baseline rendered (stitched-*: signal against signal).
enum class Comparison { rendered_ar, expected_ar, mean_spectrum, stitched };
Comparison comparison_of(std::string_view experiment_id);
std::string_view comparison_name(Comparison c);  // "rendered-ar", "expected-ar", "mean-spectrum", "stitched"

// Materials whose model / floor ratio is a number (the floor was measured).
std::size_t materials_with_floor(const Experiment& x);

// An AR oracle's two ways apart: |closed_form - monte_carlo| / monte_carlo in percent; NaN without both.
double closed_form_gap_percent(const MaterialFloor& f);
// The generating model rendered against the floor: rendered / distance (well above 1: it pays the
// texture's randomness twice); NaN without both.
double rendered_ratio(const MaterialFloor& f);

// The medians over materials of a rendering's realism figures, each over the materials where it was
// measured (NaN where none was); materials: how many have a spread ratio.
struct RealismMedians {
  double section_lsd_db = kNotMeasured, spread_ratio = kNotMeasured;
  std::size_t materials = 0;
};
RealismMedians realism_medians(const Realism& r);

}  // namespace haptex::evaluate
