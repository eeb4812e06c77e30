#pragma once
// What `haptex qa` found in one file: every check run, the error and warning counts, and the
// verdict. JSON form: schemas/qa-report.schema.json.
#include <nlohmann/json_fwd.hpp>

#include <optional>
#include <string>
#include <vector>

#include "qa/catalog.hpp"
#include "qa/check.hpp"

namespace haptex::qa {

struct Report {
  std::string file;
  FileKind kind = FileKind::recordings;
  std::optional<std::string> split;  // the manifest checked with a dataset file
  std::vector<CheckResult> checks;

  int errors() const;    // failed checks of error severity
  int warnings() const;  // failed checks of warning severity
  std::string verdict() const;  // "clean", "warnings" or "errors"
  const CheckResult* find(std::string_view id) const;
};

// Keys in the schema's order (id, severity, status, message, hint, where), for people reading it.
nlohmann::ordered_json to_json(const Report& report);

}  // namespace haptex::qa
