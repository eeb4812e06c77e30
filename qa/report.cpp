#include "qa/report.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>

namespace haptex::qa {
namespace {

int count_failed(const std::vector<CheckResult>& checks, Severity severity) {
  return int(std::count_if(checks.begin(), checks.end(), [&](const CheckResult& c) {
    return c.status == Status::fail && c.severity == severity;
  }));
}

}  // namespace

int Report::errors() const { return count_failed(checks, Severity::error); }
int Report::warnings() const { return count_failed(checks, Severity::warning); }

std::string Report::verdict() const { return errors() ? "errors" : warnings() ? "warnings" : "clean"; }

const CheckResult* Report::find(std::string_view id) const {
  const auto it = std::find_if(checks.begin(), checks.end(), [&](const CheckResult& c) { return c.id == id; });
  return it == checks.end() ? nullptr : &*it;
}

nlohmann::ordered_json to_json(const Report& report) {
  nlohmann::ordered_json checks = nlohmann::ordered_json::array();
  for (const auto& c : report.checks) {
    nlohmann::ordered_json item = {{"id", c.id},
                           {"severity", std::string(to_string(c.severity))},
                           {"status", std::string(to_string(c.status))},
                           {"message", c.message},
                           {"hint", c.hint}};
    if (!c.where.empty()) item["where"] = c.where;
    checks.push_back(std::move(item));
  }
  nlohmann::ordered_json doc = {{"file", report.file}, {"kind", std::string(to_string(report.kind))}};
  if (report.split) doc["split"] = *report.split;
  doc["checks"] = checks;
  doc["errors"] = report.errors();
  doc["warnings"] = report.warnings();
  doc["verdict"] = report.verdict();
  return doc;
}

}  // namespace haptex::qa
