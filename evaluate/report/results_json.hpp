#pragma once
// An evaluation as JSON: results.json of the report, schemas/results.schema.json.
//
// JSON has no infinities or NaN. Every floating-point value is a number when finite and otherwise
// one of the strings "inf", "-inf" or "nan" (so t = -infinity, which Welch's test gives for two
// samples without spread, keeps its sign; see evaluate/measures/welch_test.hpp), except a figure that was not
// measured (kNotMeasured: the log-spectral distances, floors, mean spectra, realism), which is null.
#include <nlohmann/json.hpp>

#include <cstddef>
#include <optional>
#include <string>

#include "evaluate/evaluation_results.hpp"
#include "evaluate/report/report_csv.hpp"

namespace haptex::evaluate {

inline constexpr const char* kResultsFormat = "results/2";  // schemas/results.schema.json
inline constexpr double kSignificanceLevel = 0.05;  // MaterialComparison::significant(): Welch, two-sided

// A double as JSON: the number, or "inf", "-inf", "nan".
nlohmann::json json_number(double x);
// A figure that may not have been measured: null for NaN, otherwise json_number.
nlohmann::json json_measured(double x);

// The whole evaluation, stamped with haptex's version and created_utc, naming each part's CSV file
// (layout); examples by name and size only, their data is in their CSVs. Follows
// schemas/results.schema.json.
nlohmann::json results_json(const Evaluation& e, const ReportLayout& layout, const std::string& created_utc);

}  // namespace haptex::evaluate
