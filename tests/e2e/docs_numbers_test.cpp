// Numbers and names in the docs that the code defines, checked against the built haptex by
// tests/e2e/docs_numbers.py (issue 35): the format table and every FAMILY/N, option defaults and
// ranges, repository paths, and the commands in code blocks. The check counts in README.md and
// docs/qa.md are tests/qa/catalog_and_layout_test.cpp's.
#include <gtest/gtest.h>

#include <string>

#include "tests/support/run_haptex.hpp"

namespace haptex::test {
namespace {

const std::string kSource = std::string(HAPTEX_SCHEMA_DIR) + "/../";

CommandResult check(const std::string& part) {
  return run_python({kSource + "tests/e2e/docs_numbers.py", part, haptex_binary(), kSource});
}

TEST(DocsNumbers, FormatVersionsAreTheOnesHaptexWrites) {
  const CommandResult r = check("formats");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
}

TEST(DocsNumbers, OptionDefaultsAndRangesAreTheHelpPages) {
  const CommandResult r = check("defaults");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
}

TEST(DocsNumbers, EveryRepositoryPathNamedExists) {
  const CommandResult r = check("paths");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
}

TEST(DocsNumbers, EveryCommandInACodeBlockExists) {
  const CommandResult r = check("commands");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
}

}  // namespace
}  // namespace haptex::test
