#pragma once
// One QA check's outcome (schemas/qa-report.schema.json, "checks" items), and the tally that condenses
// a check run over many items (recordings, presses, windows, manifest entries) into that outcome.
#include <string>
#include <string_view>
#include <vector>

namespace haptex::qa {

enum class Severity { error, warning };
enum class Status { pass, fail, skip };
std::string_view to_string(Severity severity);
std::string_view to_string(Status status);

struct CheckResult {
  std::string id;  // stable, e.g. "signal.nan" (docs/qa.md lists them all)
  Severity severity = Severity::error;
  Status status = Status::skip;
  std::string message;             // what was found, one line
  std::string hint;                // how to fix it, one line
  std::vector<std::string> where;  // the places that failed: FILE:/hdf5/path or MANIFEST#/json/pointer
};

// Collects one check's findings item by item. The check fails when any item failed, passes when at
// least one item passed and none failed, and is skipped when no item could be checked.
class CheckTally {
 public:
  // `items` names what is counted ("recordings", "presses", ...). Severity and hint come from the catalog.
  CheckTally(std::string_view id, std::string items);
  void pass() { ++passed_; }
  void fail(const std::string& where, const std::string& what);
  void skip(const std::string& why);
  // Replaces the default "N items checked" message of a passing check.
  void set_pass_message(std::string message) { pass_message_ = std::move(message); }
  std::size_t failures() const { return failures_.size(); }
  CheckResult result() const;

 private:
  std::string id_, items_, pass_message_;
  std::size_t passed_ = 0;
  std::vector<std::pair<std::string, std::string>> failures_;  // where, what
  std::vector<std::string> skips_;
};

// A check that ran once on the whole file: status and message given directly.
CheckResult make_result(std::string_view id, Status status, std::string message,
                        std::vector<std::string> where = {});

// A figure for a message, with `precision` significant digits.
std::string number(double value, int precision = 3);

}  // namespace haptex::qa
