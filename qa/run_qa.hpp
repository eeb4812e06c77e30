#pragma once
// `haptex qa`: every check that applies to a recordings, gelsight or dataset file (its kind is its
// root `haptex_format`) or to a split manifest, optionally with the manifest of a dataset file.
#include <optional>
#include <string>

#include "qa/report.hpp"

namespace haptex::qa {

struct QaOptions {
  std::string file;                  // HDF5 file or split manifest (JSON)
  std::optional<std::string> split;  // a split manifest to check with a dataset file
};

// Throws haptex::Error (bad_input) naming the file when it is missing or unreadable, is neither a
// haptex HDF5 file nor JSON, has a haptex_format qa does not check, or --split comes with a file
// that is not a dataset. Defects of a readable file are failed checks in the report, not errors.
Report run_qa(const QaOptions& options);

}  // namespace haptex::qa
