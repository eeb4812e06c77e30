// core/plot/gnuplot.hpp: labels become inert, readable gnuplot strings, checked by gnuplot itself.
#include "core/plot/gnuplot.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/process/run_program.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {
namespace fs = std::filesystem;

TEST(GnuplotText, ReplacesEveryCharacterGnuplotCouldExpand) {
  EXPECT_EQ(gnuplot::text("Brick 2"), "'Brick 2'");
  EXPECT_EQ(gnuplot::text("a'b\"c`d\\e"), "'a\u2019b\u201dc\u2018d/e'");
  EXPECT_EQ(gnuplot::text("line\nbreak\ttab\x7f"), "'line break tab '");
  EXPECT_EQ(gnuplot::text("Caf\xe9"), "'Caf\ufffd'");
  EXPECT_EQ(gnuplot::text("Caf\u00e9 \u6728"), "'Caf\u00e9 \u6728'");
  EXPECT_EQ(gnuplot::text("abcdef", 3), "'abc\u2026'");
  EXPECT_EQ(gnuplot::file(std::string(300, 'a')), "'" + std::string(300, 'a') + "'");
}

// gnuplot prints each label back exactly as text() promised, and runs nothing it spells.
TEST(GnuplotText, GnuplotPrintsTheLabelAndRunsNothing) {
  if (!process::program_on_path("gnuplot")) GTEST_SKIP() << "gnuplot is not installed";
  const TempDir dir;
  const std::string d = dir.path().string();
  // The first is issue 11's material name, aimed at this folder instead of /tmp.
  const std::vector<std::string> labels = {"Evil `touch " + d + "/x` 1' ; system 'touch " + d + "/y' ; y = '",
                                           "\"; system(\"touch z\"); \"", "@macro `touch w`", "a\\' . system('touch v') . '"};
  std::ofstream script(dir.file("print.gnuplot"));
  script << "set print '-'\n";
  for (const std::string& label : labels) script << "print " << gnuplot::text(label) << "\n";
  script.close();
  const std::string out = dir.file("out.txt");
  ASSERT_EQ(process::run_program({{"gnuplot", "print.gnuplot"}, dir.path().string(), out, "", "", {}}), 0);
  std::ifstream printed(out);
  for (const std::string& label : labels) {
    std::string line;
    ASSERT_TRUE(std::getline(printed, line));
    const std::string expected = gnuplot::text(label);
    EXPECT_EQ(line, expected.substr(1, expected.size() - 2));
  }
  for (const char* marker : {"x", "y", "z", "w", "v"}) EXPECT_FALSE(fs::exists(dir.path() / marker)) << marker;
}

}  // namespace
}  // namespace haptex::test
