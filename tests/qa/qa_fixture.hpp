#pragma once
// qa tests copy a good file of the small pipeline (tests/support/small_pipeline.hpp), break one
// thing in the copy, and expect exactly the matching check to fail.
#include <set>
#include <string>

#include "qa/report.hpp"
#include "tests/support/small_pipeline.hpp"

namespace haptex::test {

// The ids of the checks that failed.
std::set<std::string> failed_ids(const qa::Report& report);
std::string describe(const qa::Report& report);  // every failed check with its message, for test output

}  // namespace haptex::test

namespace haptex::test {

// Expects exactly one failed check, `id` (and prints every failure otherwise).
void expect_only(const qa::Report& report, const std::string& id);

}  // namespace haptex::test
