#include "evaluate/report/report_writer.hpp"

#include <algorithm>
#include <filesystem>

#include "core/durable_file.hpp"
#include "core/error.hpp"
#include "core/h5/file.hpp"
#include "core/json/schema.hpp"
#include "core/partial_directory.hpp"
#include "evaluate/report/report_charts.hpp"
#include "evaluate/report/report_csv.hpp"
#include "evaluate/report/report_html.hpp"
#include "evaluate/report/report_markdown.hpp"
#include "evaluate/report/results_json.hpp"

namespace haptex::evaluate {
namespace fs = std::filesystem;

namespace {

// report.md, report.html and results.json first, then by name.
std::vector<std::string> listed(const std::string& directory) {
  std::vector<std::string> names;
  for (const fs::directory_entry& entry : fs::directory_iterator(directory)) names.push_back(entry.path().filename().string());
  const auto rank = [](const std::string& n) { return n == "report.md" ? 0 : n == "report.html" ? 1 : n == "results.json" ? 2 : 3; };
  std::sort(names.begin(), names.end(),
            [&](const std::string& a, const std::string& b) { return std::pair(rank(a), a) < std::pair(rank(b), b); });
  return names;
}

FolderOptions report_folder(bool overwrite) { return {overwrite, "report folder", "-o", "haptex evaluate"}; }

}  // namespace

void check_report_folder(const std::string& directory, bool overwrite) { check_folder_destination(directory, report_folder(overwrite)); }

ReportFiles write_report(const Evaluation& e, const std::string& directory, bool overwrite) {
  PartialDirectory partial(directory, report_folder(overwrite));
  const std::string& dir = partial.final_path();
  const fs::path work(partial.path());
  const ReportLayout layout = report_layout(e);
  const std::string created = h5::utc_now_iso8601();

  const nlohmann::json results = results_json(e, layout, created);
  ChartResult charts;
  partial.fill([&](const std::string& work_dir) {
    write_report_csvs(e, layout, work_dir);
    json::write_file(results, "results.schema.json", (fs::path(work_dir) / "results.json").string());
    charts = write_report_charts(e, layout, work_dir);
    const std::string markdown = report_markdown(e, layout, charts, created);
    write_whole_file((fs::path(work_dir) / "report.md").string(), markdown);
    write_whole_file((fs::path(work_dir) / "report.html").string(), report_html(e, markdown, work_dir));
  });

  ReportFiles result{dir, (fs::path(dir) / "report.md").string(), results.dump(2), {}, {}, charts.note};
  for (const std::string& name : listed(work.string())) result.files.push_back((fs::path(dir) / name).string());
  for (const std::string& name : charts.images) result.charts.push_back((fs::path(dir) / name).string());
  partial.commit();
  return result;
}

}  // namespace haptex::evaluate
