#include "tests/qa/qa_fixture.hpp"

#include <gtest/gtest.h>

namespace haptex::test {

std::set<std::string> failed_ids(const qa::Report& report) {
  std::set<std::string> ids;
  for (const auto& c : report.checks)
    if (c.status == qa::Status::fail) ids.insert(c.id);
  return ids;
}

std::string describe(const qa::Report& report) {
  std::string text;
  for (const auto& c : report.checks)
    if (c.status == qa::Status::fail) text += "  " + c.id + ": " + c.message + "\n";
  return text.empty() ? "  (no check failed)\n" : text;
}

void expect_only(const qa::Report& report, const std::string& id) {
  EXPECT_EQ(failed_ids(report), std::set<std::string>{id}) << "failed checks:\n" << describe(report);
  const qa::CheckResult* check = report.find(id);
  ASSERT_NE(check, nullptr) << id << " did not run";
  EXPECT_FALSE(check->where.empty()) << id << " names no place";
  EXPECT_FALSE(check->hint.empty());
}

}  // namespace haptex::test
