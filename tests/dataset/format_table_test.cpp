// docs/architecture.md's "Formats" table is dataset/format.cpp's, row for row (issue 33: numbers in docs
// that the code can check are checked).
#include "dataset/format.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <optional>
#include <regex>
#include <set>
#include <string>

namespace haptex::dataset {
namespace {

TEST(FormatTable, TheArchitecturePageListsEveryFormatAsTheCodeDoes) {
  std::ifstream in(std::string(HAPTEX_SCHEMA_DIR) + "/../docs/architecture.md");
  const std::string page(std::istreambuf_iterator<char>(in), {});
  ASSERT_FALSE(page.empty());
  const auto kind_named = [&](const std::string& name) -> std::optional<Kind> {
    for (const Format& f : formats())
      if (format_name(f.kind) == name) return f.kind;
    return std::nullopt;
  };
  std::set<Kind> seen;
  const std::regex row("\\n\\| `([a-z]+)` \\| ([0-9]+) \\| `([^`]+)` \\| ([^\\n]*) \\|");
  for (auto it = std::sregex_iterator(page.begin(), page.end(), row); it != std::sregex_iterator(); ++it) {
    const std::optional<Kind> kind = kind_named(std::string((*it)[1]) + "/" + std::string((*it)[2]));
    ASSERT_TRUE(kind) << (*it)[1] << "/" << (*it)[2] << " is not the version this haptex writes";
    EXPECT_TRUE(seen.insert(*kind).second) << (*it)[1] << " twice";
    const Format& f = format_of(*kind);
    EXPECT_EQ((*it)[3], std::string(f.written_by)) << f.family;
    EXPECT_EQ((*it)[4], std::string(f.older)) << f.family;
  }
  for (const Format& f : formats())  // every format the code has, a new one too
    EXPECT_TRUE(seen.count(f.kind)) << format_name(f.kind) << " has no row";
}

}  // namespace
}  // namespace haptex::dataset
