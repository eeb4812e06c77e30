// haptex qa FILE [--split split.json] [--json]: check a recordings, gelsight or dataset file, or a
// split manifest, before training. Exit 1 when an error-severity check fails.
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>

#include "apps/command.hpp"
#include "core/text/utf8.hpp"
#include "qa/run_qa.hpp"

namespace haptex::apps {
namespace {

class QaCommand : public Command {
 public:
  std::string name() const override { return "qa"; }
  std::string summary() const override { return "Check a recordings, gelsight or dataset file, or a split manifest"; }
  void declare(CLI::App& app) override {
    app.add_option("file", options_.file, "recordings.h5, gelsight.h5, dataset.h5 or split.json")->required();
    app.add_option("--split", split_, "A split manifest to check together with the dataset file");
  }

  int run(const GlobalOptions& global) override {
    if (!split_.empty()) options_.split = split_;
    const qa::Report report = qa::run_qa(options_);
    if (global.json) std::cout << qa::to_json(report).dump(2) << "\n";
    else print(report, global);
    return report.errors() > 0 ? 1 : 0;
  }

 private:
  // The table: every check, or with -q only the failed ones; a failed check's fix under it, and with
  // -v every place it failed.
  static void print(const qa::Report& r, const GlobalOptions& global) {
    if (!global.quiet) {
      std::cout << "haptex qa " << text::printable(r.file) << " (" << qa::to_string(r.kind) << ")";
      if (r.split) std::cout << " with " << text::printable(*r.split);
      std::cout << "\n\n";
    }
    std::size_t width = 2;
    for (const auto& c : r.checks) width = std::max(width, c.id.size());
    const std::string indent(width + 20, ' ');
    bool header = false;
    for (const auto& c : r.checks) {
      if (global.quiet && c.status != qa::Status::fail) continue;
      if (!header) {
        std::cout << std::left << std::setw(int(width) + 2) << "ID" << std::setw(10) << "SEVERITY" << std::setw(8)
                  << "STATUS" << "MESSAGE\n";
        header = true;
      }
      std::cout << std::left << std::setw(int(width) + 2) << c.id << std::setw(10) << qa::to_string(c.severity)
                << std::setw(8) << qa::to_string(c.status) << text::printable(c.message) << "\n";  // one line: a newline in a name is escaped (review 15, R13)
      if (c.status == qa::Status::fail) {
        std::cout << indent << "fix: " << text::printable(c.hint) << "\n";
        if (global.verbose)
          for (const auto& w : c.where) std::cout << indent << "at " << text::printable(w) << "\n";
      }
    }
    if (header) std::cout << std::right << "\n";
    std::cout << "verdict: " << r.verdict() << " (" << r.errors() << " error" << (r.errors() == 1 ? "" : "s") << ", "
              << r.warnings() << " warning" << (r.warnings() == 1 ? "" : "s") << " in " << r.checks.size()
              << " checks)\n";
  }

  qa::QaOptions options_;
  std::string split_;
};

}  // namespace

std::unique_ptr<Command> make_qa_command() { return std::make_unique<QaCommand>(); }

}  // namespace haptex::apps
