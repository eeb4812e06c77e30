// Numbers and names in the docs that the code defines, checked against the built haptex by
// tests/e2e/docs_numbers.py (issue 35): the format table and every FAMILY/N, option defaults and
// ranges, repository paths, the commands in code blocks, and the figures quoted from `make demo`
// (examples/demo/run.sh, run here: about 90 s of the suite). The check counts in README.md and
// docs/qa.md are tests/qa/catalog_and_layout_test.cpp's.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/support/run_haptex.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {

const std::string kSource = std::string(HAPTEX_SCHEMA_DIR) + "/../";

CommandResult check(const std::string& part, const std::string& demo = "") {
  std::vector<std::string> args{kSource + "tests/e2e/docs_numbers.py", part, haptex_binary(), kSource};
  if (!demo.empty()) args.push_back(demo);
  return run_python(args);
}

// formats: the format table and every FAMILY/N; defaults: option defaults and ranges against --help;
// paths: every repository path named exists; commands: every `haptex WORD` in a code block is one.
class DocsNumbersPart : public ::testing::TestWithParam<const char*> {};

TEST_P(DocsNumbersPart, AgreesWithTheCode) {
  const CommandResult r = check(GetParam());
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
}

INSTANTIATE_TEST_SUITE_P(DocsNumbers, DocsNumbersPart, ::testing::Values("formats", "defaults", "paths", "commands"));

TEST(DocsNumbers, FiguresQuotedFromTheDemoAreTheDemosOwn) {
  TempDir dir;
  const CommandResult demo = run_program({kSource + "examples/demo/run.sh", haptex_binary(), dir.file("demo")});
  ASSERT_EQ(demo.exit_code, 0) << demo.out << demo.err;
  const CommandResult r = check("demo", dir.file("demo"));
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
}

}  // namespace
}  // namespace haptex::test
