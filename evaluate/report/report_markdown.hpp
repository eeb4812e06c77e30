#pragma once
// report.md: an evaluation told for a reader who has nothing else at hand: what was compared (inputs
// with their SHA-256, settings), what the measures and each experiment are, which comparison answers
// which question, a totals table (with the paper's figure beside ours where the experiment is the
// paper's), per experiment its totals sentence, its standing against the noise floor (a warning for
// any material below it; for a comparison with the mean training spectrum, every material where the
// model is significantly worse, by name), chart and per-material table; the noise floor, the realism
// of rendered signals, the examples, the texture map, the speed-vs-accuracy table, the notes and the
// list of files. Charts are relative image links; a figure that was not measured shows as "–".
#include <string>

#include "evaluate/evaluation_results.hpp"
#include "evaluate/report/report_charts.hpp"
#include "evaluate/report/report_csv.hpp"

namespace haptex::evaluate {

// charts: which PNGs exist (a chart not drawn is named with its CSV and script instead) and the
// charts' note, which joins e.notes.
std::string report_markdown(const Evaluation& e, const ReportLayout& layout, const ChartResult& charts,
                            const std::string& created_utc);

// "better on X of N materials, significantly on Y, significantly worse on Z"
std::string totals_sentence(const Experiment& x);

// Four significant digits, fixed-point from 0.001 to 99 999, otherwise scientific (1.234e-05);
// +∞, -∞ and n/a for what is not finite.
std::string format_number(double x);
// A p-value: three significant digits, scientific below 0.001 (1.30e-05), 0 as 0.
std::string format_p(double p);

}  // namespace haptex::evaluate
