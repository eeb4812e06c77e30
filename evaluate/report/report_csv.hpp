#pragma once
// The data of an evaluation report as CSV files, and the names of all the report's files.
//
// CSV as RFC 4180 reads it: comma-separated, one header row, a field holding a comma, a double quote
// or a line break is quoted ("Brick, 2" -> "\"Brick, 2\""), quotes doubled. Numbers are written in the
// shortest form that reads back to the same double (std::to_chars); infinities and NaN as `inf`,
// `-inf` and `nan`, which strtod, numpy.loadtxt and pandas.read_csv all read, except a figure that was
// not measured (kNotMeasured), which leaves its cell empty. Booleans are 1 or 0.
#include <string>
#include <string_view>
#include <vector>

#include "evaluate/evaluation_results.hpp"

namespace haptex::evaluate {

// File names (without extension) inside the report folder, shared by the CSV, chart and markdown
// writers. Experiment and example ids become file names with every character outside
// [A-Za-z0-9._-] replaced by '_', made unique with a -2, -3 ... suffix.
struct ReportLayout {
  std::vector<std::string> experiments;  // per experiment: "experiment-<id>": .csv, .gnuplot, .png
  std::vector<std::string> examples;     // per example: "example-<id>": -spectra.csv, -signals.csv
};
ReportLayout report_layout(const Evaluation& e);

inline constexpr std::string_view kSpeedStem = "speed";        // speed.csv, .gnuplot, .png
inline constexpr std::string_view kLatentsStem = "latents";    // latents.csv, .gnuplot, .png
inline constexpr std::string_view kExamplesStem = "examples";  // examples.gnuplot, .png (Fig. 5)
inline constexpr std::string_view kFloorsStem = "floors";      // floors.csv
inline constexpr std::string_view kRealismStem = "realism";    // realism.csv

// Column headers, in order.
inline constexpr std::string_view kExperimentColumns =
    "material_id,name,windows,model_distance,baseline_distance,difference_q1,difference_median,difference_q3,"
    "t,df,p,n_model,n_baseline,better,significant,model_lsd_db,baseline_lsd_db,floor,floor_ratio,mean_spectrum,"
    "mean_spectrum_ratio,below_floor";
inline constexpr std::string_view kSpeedColumns = "method,setting,seconds_per_second,distance,kind,section_lsd_db,spread_ratio";
inline constexpr std::string_view kFloorColumns =
    "material_id,name,kind,method,windows,distance,lsd_db,closed_form,monte_carlo,closed_form_gap_percent,rendered,"
    "rendered_ratio,estimate,baseline_expected,input_floor";
inline constexpr std::string_view kRealismColumns =
    "method,setting,material_id,name,section_lsd_db,spread_ratio,distance,floor_ratio,rendered_floor_ratio";
inline constexpr std::string_view kLatentColumns = "material_id,name,kind,x,y";
inline constexpr std::string_view kSpectraColumns = "frequency_hz,truth,model,baseline";
inline constexpr std::string_view kSignalColumns = "time_s,truth,model,baseline";

std::string csv_field(std::string_view text);  // quoted when it has to be
std::string csv_number(double x);              // shortest round-trip form; inf, -inf, nan
std::string csv_measured(double x);            // csv_number, but empty for NaN (not measured)

// Writes every CSV of the report into directory (which exists): one per experiment (a row per
// material), speed.csv, latents.csv, floors.csv (a row per material), realism.csv (a row per
// rendering method and material), and two per example (the spectra of one test window: 10 Hz
// steps from 10 Hz; the first samples of the stitched signals: time from 0 at 10 kHz; a shorter
// series leaves its cells empty). Returns the paths written. Throws haptex::Error (failed) when a
// file cannot be written.
std::vector<std::string> write_report_csvs(const Evaluation& e, const ReportLayout& layout, const std::string& directory);

}  // namespace haptex::evaluate
