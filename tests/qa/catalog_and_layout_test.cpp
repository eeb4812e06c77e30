// The check catalog, docs/qa.md and the report stay in step; the layout tables parse as the checks
// need them.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/h5/file.hpp"
#include "core/json/schema.hpp"
#include "qa/catalog.hpp"
#include "qa/layout_spec.hpp"
#include "qa/report.hpp"
#include "qa/run_qa.hpp"
#include "tests/qa/qa_fixture.hpp"

namespace haptex::test {
namespace {

std::string docs_page() {
  std::ifstream in(std::string(HAPTEX_SCHEMA_DIR) + "/../docs/qa.md");
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(Catalog, EveryCheckIsDocumentedWithItsSeverityAndFix) {
  const std::string page = docs_page();
  ASSERT_FALSE(page.empty());
  std::set<std::string> ids;
  for (const auto& c : qa::all_checks()) {
    EXPECT_TRUE(ids.insert(std::string(c.id)).second) << c.id << " twice";
    EXPECT_TRUE(std::regex_match(std::string(c.id), std::regex("^[a-z]+(\\.[a-z_]+)+$"))) << c.id;
    const std::string row = "| `" + std::string(c.id) + "` | " + std::string(qa::to_string(c.severity)) + " |";
    const auto at = page.find(row);
    ASSERT_NE(at, std::string::npos) << "docs/qa.md has no row " << row;
    const std::string line = page.substr(at, page.find('\n', at) - at);
    EXPECT_NE(line.find(std::string(c.hint)), std::string::npos) << c.id << ": the page's fix differs from the catalog's";
  }
  // And the page documents no check that does not exist.
  const std::regex documented("\\| `([a-z]+\\.[a-z_]+)` \\| (error|warning) \\|");
  for (auto it = std::sregex_iterator(page.begin(), page.end(), documented); it != std::sregex_iterator(); ++it)
    EXPECT_TRUE(ids.count((*it)[1])) << (*it)[1] << " is documented but not in the catalog";
}

// README's command table says how many checks there are (issue 33: numbers in docs are tested).
TEST(Catalog, TheReadmeCountsTheChecks) {
  std::ifstream in(std::string(HAPTEX_SCHEMA_DIR) + "/../README.md");
  const std::string readme(std::istreambuf_iterator<char>(in), {});
  std::smatch m;
  ASSERT_TRUE(std::regex_search(readme, m, std::regex("\\| ([0-9]+) checks with stable IDs"))) << "README names no count of checks";
  EXPECT_EQ(std::stoul(m[1]), qa::all_checks().size());
}

// docs/qa.md, "The checks": the catalog and the code read side by side.
TEST(Catalog, EveryCheckIsOneFunctionNamedAfterIt) {
  std::string sources;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(HAPTEX_SCHEMA_DIR) + "/../qa"))
    if (entry.path().extension() == ".cpp") {
      std::ifstream in(entry.path());
      sources += std::string(std::istreambuf_iterator<char>(in), {});
    }
  ASSERT_FALSE(sources.empty());
  for (const auto& c : qa::all_checks()) {
    std::string name = "check_" + std::string(c.id);
    std::replace(name.begin(), name.end(), '.', '_');
    const bool defined = sources.find("\nCheckResult " + name + "(") != std::string::npos ||
                         sources.find("\nvoid " + name + "(") != std::string::npos;
    EXPECT_TRUE(defined) << c.id << ": no function " << name << " in qa/*.cpp";
  }
}

TEST(Catalog, ReportsListEveryApplicableCheckOnceInCatalogOrder) {
  const qa::Report r = qa::run_qa({small_pipeline().dataset, small_pipeline().split});
  std::vector<std::string> reported;
  for (const auto& c : r.checks) reported.push_back(c.id);
  std::vector<std::string> catalog;
  for (const auto& c : qa::all_checks()) catalog.emplace_back(c.id);
  EXPECT_EQ(reported, catalog);  // a dataset with its split runs every check there is
  EXPECT_THROW(qa::check_info("signal.nope"), Error);
}

TEST(Catalog, JsonReportFollowsItsSchema) {
  TempDir dir;
  const std::string copy = copy_into(dir, small_pipeline().recordings, "r.h5");
  h5::File::open(copy, true).root().open_group("materials/woven_1/recordings/0").set_attr("duration_s", 6.0);
  const qa::Report r = qa::run_qa({copy, {}});
  const nlohmann::json doc = nlohmann::json::parse(qa::to_json(r).dump());
  EXPECT_NO_THROW(json::validate(doc, "qa-report.schema.json", "report"));
  EXPECT_EQ(doc["verdict"], "errors");
  EXPECT_EQ(doc["errors"], 1);
  EXPECT_FALSE(doc.contains("split"));
  bool found = false;
  for (const auto& c : doc["checks"])
    if (c["id"] == "signal.duration") {
      found = true;
      EXPECT_EQ(c["status"], "fail");
      EXPECT_EQ(c["where"], nlohmann::json::array({"/materials/woven_1/recordings/0"}));
    } else {
      EXPECT_FALSE(c.contains("where")) << c.dump();
    }
  EXPECT_TRUE(found);
}

TEST(Layout, SectionsOfEveryFormatQaChecks) {
  const auto& layout = qa::embedded_layout();
  for (const char* format : {"recordings/1", "gelsight/2", "dataset/4"}) EXPECT_TRUE(qa::layout_has_format(layout, format)) << format;
  const auto rows = qa::rows_for_format(layout, "recordings/1");
  const auto accel = std::find_if(rows.begin(), rows.end(), [](const auto& r) {
    return r.path == "/materials/{material}/recordings/{k}/accel_xyz";
  });
  ASSERT_NE(accel, rows.end());
  EXPECT_EQ(accel->dtype, "float32");
  EXPECT_EQ(accel->shape, (std::vector<std::string>{"N", "3"}));
  EXPECT_EQ(accel->units, "m/s^2");
  EXPECT_TRUE(accel->always);
  EXPECT_TRUE(accel->attribute.empty());
}

TEST(Layout, DatasetRowsIncludeTheCopiedRecordingsAndPresses) {
  const auto rows = qa::rows_for_format(qa::embedded_layout(), "dataset/4");
  auto has = [&](const std::string& path) {
    return std::any_of(rows.begin(), rows.end(), [&](const auto& r) { return r.path == path; });
  };
  EXPECT_TRUE(has("/@haptex_format"));
  EXPECT_TRUE(has("/windows/@stride"));
  EXPECT_TRUE(has("/materials/{material}/recordings/{k}/speed_lp"));
  EXPECT_TRUE(has("/materials/{material}/presses/{j}/frames"));
  EXPECT_FALSE(has("/@field_map"));                      // a recordings file's root attribute
  EXPECT_FALSE(has("/materials/{material}/spectrum"));  // the truth file's
  EXPECT_TRUE(has("/shards/{s}/@sha256"));              // a merged file's provenance, optional
}

TEST(Layout, ParsesAttributesOptionalRowsAndRefusesBrokenTables) {
  const auto sections = qa::parse_layout(
      "# t\n\n## Every file\n\n| path | dtype | shape | units | required when |\n|---|---|---|---|---|\n"
      "| `/@a` | string | () | | always |\n\n## Thing file (`haptex_format` = `thing/2`, written by x)\n\n"
      "| `/g/{i}/@n` | int64 | () | | always |\n| `/g/{i}/d` | float64 | (N, 2) | mm | the source has it |\n");
  ASSERT_EQ(sections.size(), 2u);
  EXPECT_EQ(sections[1].format, "thing/2");
  ASSERT_EQ(sections[1].rows.size(), 2u);
  EXPECT_EQ(sections[1].rows[0].owner, "/g/{i}");
  EXPECT_EQ(sections[1].rows[0].attribute, "n");
  EXPECT_TRUE(sections[1].rows[0].shape.empty());
  EXPECT_FALSE(sections[1].rows[1].always);
  EXPECT_EQ(sections[1].rows[1].line, 12);
  EXPECT_EQ(qa::rows_for_format(sections, "thing/2").size(), 3u);
  EXPECT_THROW(qa::parse_layout("## Every file\n| `/@a` | string | () |\n"), Error);
  EXPECT_THROW(qa::parse_layout("## Every file\n| `/@a` | string | N | | always |\n"), Error);
}

}  // namespace
}  // namespace haptex::test
