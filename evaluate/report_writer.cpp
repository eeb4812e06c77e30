#include "evaluate/report_writer.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "core/durable_file.hpp"
#include "core/error.hpp"
#include "core/h5/file.hpp"
#include "core/json/schema.hpp"
#include "core/owned_folder.hpp"
#include "evaluate/report_charts.hpp"
#include "evaluate/report_csv.hpp"
#include "evaluate/report_markdown.hpp"
#include "evaluate/results_json.hpp"

namespace haptex::evaluate {
namespace fs = std::filesystem;

namespace {

std::string parent_of(const std::string& path) {
  const fs::path parent = fs::path(path).parent_path();
  return parent.empty() ? "." : parent.string();
}

void check_destination(const std::string& dir, bool overwrite) {
  const std::string name = fs::path(dir).filename().string();
  if (name.empty() || name == "." || name == "..")
    throw input_error(dir, "", "not a name for a new report folder", "Name the folder with -o, e.g. -o report");
  const std::string parent = parent_of(dir);
  std::error_code ec;
  if (!fs::is_directory(parent, ec))
    throw input_error(dir, "", "the folder " + parent + " that should hold the report does not exist",
                      "Create it first or choose another -o");
  if (::access(parent.c_str(), W_OK) != 0)
    throw input_error(dir, "", "the folder " + parent + " is not writable", "Choose a folder you can write to with -o");
  const fs::file_status status = fs::symlink_status(dir, ec);
  if (!fs::exists(status)) return;
  if (!fs::is_directory(status))
    throw input_error(dir, "", "exists and is not a folder", "Choose another -o, or move it out of the way");
  if (!overwrite)
    throw input_error(dir, "", "the report folder already exists",
                      "Remove it, choose another -o, or pass --force to replace it");
  check_only_haptex_files(dir);
}

// DIR.partial: created (or, left by a killed run, emptied), locked while this object lives, removed
// unless committed.
class PartialDirectory {
 public:
  explicit PartialDirectory(std::string final_path) : final_(std::move(final_path)), path_(final_ + ".partial") {
    std::error_code ec;
    fs::create_directory(path_, ec);
    if (ec)
      throw input_error(final_, "", "cannot create " + path_ + " (" + ec.message() + ")",
                        "Choose a folder you can write to with -o, or remove " + path_);
    fd_ = ::open(path_.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd_ < 0)
      throw input_error(final_, "", "cannot open " + path_ + ": " + std::strerror(errno), "Remove " + path_ + " by hand");
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      ::close(fd_);
      throw input_error(final_, "", "another haptex run is writing this report right now (" + path_ + " is locked)",
                        "Wait for it to finish, or choose another -o");
    }
    for (const fs::directory_entry& entry : fs::directory_iterator(path_)) fs::remove_all(entry.path());
  }
  ~PartialDirectory() {
    std::error_code ignored;
    if (!committed_) fs::remove_all(path_, ignored);
    if (fd_ >= 0) ::close(fd_);
  }
  PartialDirectory(const PartialDirectory&) = delete;
  PartialDirectory& operator=(const PartialDirectory&) = delete;

  const std::string& path() const { return path_; }

  // Syncs every file and the folder, then renames it to the final name; an existing report folder
  // (overwrite) is swapped out in one step and then removed.
  void commit(bool overwrite) {
    write_file_list(path_, "haptex evaluate");
    for (const fs::directory_entry& entry : fs::directory_iterator(path_)) fsync_path(entry.path().string(), O_RDONLY);
    fsync_path(path_, O_RDONLY | O_DIRECTORY);
    std::error_code ec;
    const bool replace = fs::exists(fs::symlink_status(final_, ec));
    if (replace) check_destination(final_, overwrite);  // it appeared while we wrote, or it is not a folder
    const int status = replace ? ::renameat2(AT_FDCWD, path_.c_str(), AT_FDCWD, final_.c_str(), RENAME_EXCHANGE)
                               : std::rename(path_.c_str(), final_.c_str());
    if (status != 0)
      throw failure(path_ + ": cannot rename to " + final_ + ": " + std::strerror(errno) +
                    (replace ? " (remove the old report folder and run again)" : ""));
    committed_ = true;
    fsync_path(parent_of(final_), O_RDONLY | O_DIRECTORY);
    if (replace) {
      fs::remove_all(path_, ec);  // the old report, swapped here
      if (ec)
        throw failure("the new report is complete in " + final_ + ", but the old one, moved to " + path_ +
                      ", could not be removed: " + ec.message());
    }
  }

 private:
  std::string final_, path_;
  int fd_ = -1;
  bool committed_ = false;
};

// report.md and results.json first, then by name.
std::vector<std::string> listed(const std::string& directory) {
  std::vector<std::string> names;
  for (const fs::directory_entry& entry : fs::directory_iterator(directory)) names.push_back(entry.path().filename().string());
  const auto rank = [](const std::string& n) { return n == "report.md" ? 0 : n == "results.json" ? 1 : 2; };
  std::sort(names.begin(), names.end(),
            [&](const std::string& a, const std::string& b) { return std::pair(rank(a), a) < std::pair(rank(b), b); });
  return names;
}

}  // namespace

ReportFiles write_report(const Evaluation& e, const std::string& directory, bool overwrite) {
  std::string dir = directory;
  while (dir.size() > 1 && dir.back() == '/') dir.pop_back();
  check_destination(dir, overwrite);
  PartialDirectory partial(dir);
  const fs::path work(partial.path());
  const ReportLayout layout = report_layout(e);
  const std::string created = h5::utc_now_iso8601();

  write_report_csvs(e, layout, work.string());
  const nlohmann::json results = results_json(e, layout, created);
  json::write_file(results, "results.schema.json", (work / "results.json").string());
  const ChartResult charts = write_report_charts(e, layout, work.string());
  write_text_file((work / "report.md").string(), report_markdown(e, layout, charts, created));

  ReportFiles result{dir, (fs::path(dir) / "report.md").string(), results.dump(2), {}, {}, charts.note};
  for (const std::string& name : listed(work.string())) result.files.push_back((fs::path(dir) / name).string());
  for (const std::string& name : charts.images) result.charts.push_back((fs::path(dir) / name).string());
  partial.commit(overwrite);
  return result;
}

}  // namespace haptex::evaluate
