// haptex info FILE [--json]: what a haptex HDF5 file holds.
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>

#include "apps/command.hpp"
#include "core/text/utf8.hpp"
#include "info/file_summary.hpp"

namespace haptex::apps {
namespace {

std::string shape_text(const std::vector<std::uint64_t>& shape) {
  std::string text;
  for (auto extent : shape) text += (text.empty() ? "" : " x ") + std::to_string(extent);
  return text.empty() ? "scalar" : text;
}

class InfoCommand : public Command {
 public:
  std::string name() const override { return "info"; }
  std::string summary() const override { return "Summarise a haptex HDF5 file"; }
  void declare(CLI::App& app) override { app.add_option("file", file_, "haptex HDF5 file")->required(); }

  int run(const GlobalOptions& global) override {
    const info::FileSummary summary = info::summarize_file(file_);
    if (global.json) {
      // A format attribute that is not UTF-8 is shown, not refused (docs/info.md): as U+FFFD in JSON.
      std::cout << info::to_json(summary).dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
      return 0;
    }
    print(summary, global.verbose > 0);
    return 0;
  }

 private:
  static void print(const info::FileSummary& s, bool every_dataset) {
    // Every string in the file is shown escaped: a name's control characters never reach the terminal.
    const auto shown = [](const std::string& t) { return text::printable(t); };
    std::cout << shown(s.path) << " (" << s.bytes << " bytes)\n"
              << "  format   " << shown(text::shortened(s.format)) << (s.format_remark.empty() ? "" : " (" + s.format_remark + ")")
              << ", written by haptex " << shown(s.version) << " at " << shown(s.created_utc) << "\n"
              << "  source   " << shown(s.source) << "\n"
              << "  materials " << s.materials.size() << "\n";
    for (const auto& m : s.materials) {
      std::cout << "  " << shown(m.id) << " (" << shown(m.name) << ")\n";
      for (const auto& c : m.collections) {
        std::cout << "    " << shown(c.name) << ": " << c.items.size() << "\n";
        for (const auto& item : c.items) print_item(item, every_dataset);
      }
    }
    for (const auto& d : s.other_datasets)
      std::cout << "  " << shown(d.name) << "  " << d.dtype << " [" << shape_text(d.shape) << "]\n";
  }

  // One line per item; with -v, every dataset with its dtype, shape and units.
  static void print_item(const info::ItemSummary& item, bool every_dataset) {
    std::cout << "      " << text::printable(item.key) << ":";
    if (item.duration_s) std::cout << " " << std::fixed << std::setprecision(2) << *item.duration_s << " s";
    if (item.sample_rate_hz) std::cout << " at " << std::setprecision(0) << *item.sample_rate_hz << " Hz";
    std::cout << std::defaultfloat;
    if (!every_dataset) {
      std::string names;
      for (const auto& d : item.datasets) names += (names.empty() ? "" : ", ") + text::printable(d.name);
      std::cout << "  [" << names << "]\n";
      return;
    }
    std::cout << "\n";
    for (const auto& d : item.datasets)
      std::cout << "        " << std::left << std::setw(18) << text::printable(d.name) << std::setw(9) << d.dtype << std::setw(14)
                << "[" + shape_text(d.shape) + "]" << d.units << std::right << "\n";
  }

  std::string file_;
};

}  // namespace

std::unique_ptr<Command> make_info_command() { return std::make_unique<InfoCommand>(); }

}  // namespace haptex::apps
