// core/text/shell_quote: words a shell reads as they are stay as they are; others are single-quoted so
// that a POSIX shell's word splitting (python's shlex, which runs nothing) gives them back.
#include "core/text/shell_quote.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/support/run_haptex.hpp"

namespace haptex::text {
namespace {

TEST(ShellQuote, PlainWordsStayAsTheyAre) {
  EXPECT_EQ(shell_quoted("fake:size=320x240,lockstep"), "fake:size=320x240,lockstep");
  EXPECT_EQ(shell_quoted("/tmp/a_b-c.h5"), "/tmp/a_b-c.h5");
  EXPECT_EQ(shell_quoted("Cork"), "Cork");
}

TEST(ShellQuote, OtherWordsAreQuoted) {
  EXPECT_EQ(shell_quoted(""), "''");
  EXPECT_EQ(shell_quoted("Brick 2"), "'Brick 2'");
  EXPECT_EQ(shell_quoted("Bob's"), "'Bob'\\''s'");
}

TEST(ShellQuote, AShellSplitsThemBackIntoTheSameWords) {
  if (!test::python_has("shlex")) GTEST_SKIP() << "python3 is not installed";
  const std::vector<std::string> words{"a b", "it's", "`id`", "$(id)", "$HOME", "\"q\"", "back\\slash", "new\nline", "", "*", "x;y&z|w", "ü"};
  std::string line;
  for (const std::string& w : words) line += (line.empty() ? "" : " ") + shell_quoted(w);
  const test::CommandResult r = test::run_python({"-c", "import json, shlex, sys; print(json.dumps(shlex.split(sys.argv[1])))", line});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out).get<std::vector<std::string>>(), words) << line;
}

}  // namespace
}  // namespace haptex::text
