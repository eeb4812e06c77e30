#pragma once
// The report folder of `haptex evaluate -o DIR`: report.md (readable on its own), results.json
// (schemas/results.schema.json), the CSVs, gnuplot scripts and, when gnuplot is installed, the
// charts as PNG. See docs/evaluate.md, "The report".
//
// Atomic as a whole (docs/architecture.md, "Modules"): everything is written into DIR.partial (locked against a
// second run writing the same report; a leftover of a killed run is emptied and reused), synced,
// and renamed to DIR at the end, so a failure never leaves a half report under DIR, nor a
// DIR.partial behind.
#include <string>
#include <vector>

#include "evaluate/evaluation_results.hpp"

namespace haptex::evaluate {

struct ReportFiles {
  std::string directory;            // DIR as given, without trailing slashes
  std::string report;               // DIR/report.md
  std::string results_json_text;    // what results.json holds (for a command's --json output)
  std::vector<std::string> files;   // every file written, as DIR/NAME: report.md, results.json, then by name
  std::vector<std::string> charts;  // the PNGs drawn, as DIR/NAME
  std::string note;                 // empty, or why charts are missing (gnuplot not installed or failed)
};

// Throws haptex::Error (bad_input) naming DIR when DIR exists and overwrite is false (the existing
// folder is left untouched), when DIR exists but is not a folder, when its parent folder is missing
// or not writable, or when another run is writing DIR.partial; (failed) when writing fails. With
// overwrite, an existing DIR is replaced in one step (renameat2 RENAME_EXCHANGE) only once the new
// report is complete.
ReportFiles write_report(const Evaluation& e, const std::string& directory, bool overwrite);
// write_report's refusals that need no evaluation, for before it runs (review 14, F3).
void check_report_folder(const std::string& directory, bool overwrite);

}  // namespace haptex::evaluate
