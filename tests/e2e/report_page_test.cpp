// The pages a user opens (issue 34): evaluate's report.html, where every table and chart of report.md is
// on the page, every material has its three players and the embedded WAVs read back (Python's wave
// module) at 48 kHz; and haptex view's dataset page. A real browser (headless Chromium, where
// installed) loads every image and every audio element of each; screenshots are kept beside the
// build's binary (build/report_page.png, build/dataset_page.png).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "core/json/schema.hpp"
#include "tests/support/browser.hpp"
#include "tests/support/quick_models.hpp"
#include "tests/support/run_haptex.hpp"
#include "tests/support/small_pipeline.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {
namespace fs = std::filesystem;

std::string text_of(const std::string& path) {
  std::stringstream s;
  s << std::ifstream(path).rdbuf();
  return s.str();
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

// One evaluation report of the small pipeline, made once.
const std::string& report_folder() {
  static const TempDir dir;
  static const std::string folder = [] {
    const SmallPipeline& p = small_pipeline();
    const CommandResult r = run_haptex({"evaluate", p.dataset, "--split", p.split, "--model", quick_model(false), "-o", dir.file("rep")});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return dir.file("rep");
  }();
  return folder;
}

std::size_t materials() { return json::read_file(small_pipeline().split)["materials"].size(); }

// Screenshots go beside the build's binary (build/), wherever the tests run from.
std::string screenshot(const std::string& name) { return (fs::path(HAPTEX_BINARY).parent_path() / name).string(); }

TEST(ReportPage, HoldsEveryTableChartAndMaterialOfTheMarkdown) {
  const std::string md = text_of(report_folder() + "/report.md"), html = text_of(report_folder() + "/report.html");
  ASSERT_FALSE(html.empty());
  EXPECT_EQ(count(html, "<table class=\"sortable\">"), count(md, "\n|---")) << "every table";
  std::size_t charts = 0;
  for (const fs::directory_entry& f : fs::directory_iterator(report_folder())) charts += f.path().extension() == ".png";
  EXPECT_EQ(count(html, "<figure><img src=\"data:image/png;base64,"), charts) << "every chart drawn, embedded";
  EXPECT_EQ(count(html, "<section class=\"material\""), materials());
  EXPECT_EQ(count(html, "<audio controls"), 3 * materials());
  EXPECT_EQ(count(html, "alt=\"test press of "), materials());
  EXPECT_EQ(count(html, "src=\"http"), 0u) << "self-contained";
  const nlohmann::json listed = json::read_file(report_folder() + "/haptex-files.json");
  EXPECT_NE(listed.dump().find("report.html"), std::string::npos) << "--force may replace it with the report";
}

TEST(ReportPage, ItsWavsAre48kHzClipsOfTheTestSectionsInOrder) {
  if (!python_has("json")) GTEST_SKIP() << "python3 is missing";
  const CommandResult r = run_python({std::string(HAPTEX_SCHEMA_DIR) + "/../tests/e2e/report_page_test.py", report_folder() + "/report.html"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json players = nlohmann::json::parse(r.out);
  ASSERT_EQ(players.size(), 3 * materials());
  for (const nlohmann::json& p : players) {
    SCOPED_TRACE(p.dump());
    EXPECT_EQ(p["rate"], 48000);
    EXPECT_EQ(p["width"], 2);
    EXPECT_EQ(p["channels"], 1);
    EXPECT_GT(p["frames"], 480) << "more than 10 ms";
  }
  // Each material's caption says how long its clips are and how many test sections they join; its
  // three players (recorded, model, baseline) are that long.
  const std::string html = text_of(report_folder() + "/report.html");
  const std::regex caption(R"((\d+\.\d\d) s: (\d+) test sections?)");
  std::size_t material = 0, joined = 0;
  for (auto m = std::sregex_iterator(html.begin(), html.end(), caption); m != std::sregex_iterator(); ++m, ++material) {
    ASSERT_LT(material, materials());
    const double seconds = std::stod((*m)[1]);
    joined += std::stoul((*m)[2]) > 1;
    for (std::size_t k = 0; k < 3; ++k) EXPECT_NEAR(players[3 * material + k]["frames"].get<double>(), seconds * 48000, 240) << (*m)[0];
  }
  EXPECT_EQ(material, materials());
  EXPECT_GT(joined, 0u) << "the small pipeline has materials with several test sections; their clips run on over them";
}

// Review 12, C1: names with markup characters showed report.md's escape backslashes on the page, and a
// back-quote in a path was written ' (a file that does not exist). Both pages show names as they are.
TEST(ReportPage, NamesShowAsTheyAreInBothPages) {
  const SmallPipeline& p = small_pipeline();
  const TempDir dir;
  const std::string folder = dir.file("x`$(id)<b>#|");
  fs::create_directory(folder);
  for (const auto& [from, to] : {std::pair{p.dataset, "d.h5"}, {p.split, "s.json"}, {quick_model(false), "m<i>.h5"}})
    fs::copy_file(from, folder + "/" + to);
  const CommandResult r = run_haptex({"evaluate", folder + "/d.h5", "--split", folder + "/s.json", "--model", folder + "/m<i>.h5", "--repeats", "2",
                                      "--reconstruct", "none", "-o", dir.file("rep")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string html = text_of(dir.file("rep/report.html")), md = text_of(dir.file("rep/report.md"));
  EXPECT_NE(html.find("<code>" + dir.file("x`$(id)&lt;b&gt;#|") + "/d.h5</code>"), std::string::npos) << "the path as it is";
  EXPECT_NE(html.find("m&lt;i&gt;.h5"), std::string::npos);
  EXPECT_EQ(html.find("\\&lt;"), std::string::npos) << "no Markdown escape shown";
  EXPECT_EQ(html.find("\\#"), std::string::npos) << "no Markdown escape shown";
  EXPECT_NE(md.find("x`$(id)<b>#\\|/d.h5"), std::string::npos) << "report.md's code keeps the back-quote";
}

TEST(ReportPage, ABrowserLoadsEveryImageAndPlayer) {
  if (!browser_installed()) GTEST_SKIP() << "chromium is not installed (make deps installs it): the page was checked, not opened";
  const std::string shot = screenshot("report_page.png");
  const nlohmann::json check = browser_load_check(report_folder() + "/report.html", shot);
  ASSERT_FALSE(check.is_null()) << "the page's load check did not finish";
  EXPECT_EQ(check["image_errors"].size(), 0u) << check.dump();
  EXPECT_EQ(check["audio_errors"].size(), 0u) << check.dump();
  EXPECT_EQ(check["audio"].size(), 3 * materials());
  for (const nlohmann::json& a : check["audio"]) EXPECT_GT(double(a["seconds"]), 0.01) << a.dump();
  EXPECT_EQ(std::size_t(check["images"]), count(text_of(report_folder() + "/report.html"), "<img "));
  EXPECT_TRUE(fs::exists(shot));
}

// haptex view: the dataset's page, before any model.
TEST(DatasetPage, ShowsEveryMaterialsPressesCoverageSpectrumAndRecordings) {
  const SmallPipeline& p = small_pipeline();
  const TempDir dir;
  const CommandResult r = run_haptex({"--json", "view", p.dataset, "--split", p.split, "-o", dir.file("site")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string html = text_of(dir.file("site/index.html"));
  EXPECT_EQ(count(html, "<section class=\"material\""), materials());
  EXPECT_EQ(count(html, "aria-label=\"coverage\""), materials());
  EXPECT_EQ(count(html, "aria-label=\"spectra\""), materials());
  EXPECT_NE(html.find("<span style=\"color:#2ca02c\">test</span>"), std::string::npos) << "coloured by set";
  EXPECT_GE(count(html, "<audio controls"), materials()) << "every recording";
  EXPECT_GE(count(html, ", peak\" src=\"data:image/png"), materials()) << "every press's peak";
  // Without --split the windows are one colour, and the page says how to colour them.
  ASSERT_EQ(run_haptex({"view", p.dataset, "-o", dir.file("plain")}).exit_code, 0);
  EXPECT_NE(text_of(dir.file("plain/index.html")).find("give --split to colour them by set"), std::string::npos);
  // --force replaces only the page haptex wrote.
  EXPECT_EQ(run_haptex({"view", p.dataset, "-o", dir.file("site")}).exit_code, 2);
  EXPECT_EQ(run_haptex({"view", p.dataset, "-o", dir.file("site"), "--force"}).exit_code, 0);
  if (!browser_installed()) GTEST_SKIP() << "chromium is not installed (make deps installs it): the page was checked, not opened";
  const nlohmann::json check = browser_load_check(dir.file("site/index.html"), screenshot("dataset_page.png"));
  ASSERT_FALSE(check.is_null()) << "the page's load check did not finish";
  EXPECT_EQ(check["image_errors"].size(), 0u) << check.dump();
  EXPECT_EQ(check["audio_errors"].size(), 0u) << check.dump();
  EXPECT_EQ(std::size_t(check["images"]), count(html, "<img "));
  EXPECT_EQ(check["audio"].size(), count(html, "<audio controls"));
  for (const nlohmann::json& a : check["audio"]) EXPECT_NEAR(double(a["seconds"]), 3.0, 0.01) << a.dump();
}

}  // namespace
}  // namespace haptex::test
