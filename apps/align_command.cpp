// haptex align --recordings recordings.h5 --gelsight gelsight.h5 -o dataset.h5 [--stride 100] [--names map.json]
#include <chrono>
#include <iostream>
#include <nlohmann/json.hpp>

#include "align/align_dataset.hpp"
#include "apps/command.hpp"
#include "apps/output_options.hpp"
#include "core/output_is_input.hpp"
#include "apps/terminal_progress.hpp"
#include "core/text/utf8.hpp"

namespace haptex::apps {
namespace {

std::vector<std::string> names_of(const std::vector<align::NamedMaterial>& list) {
  std::vector<std::string> names;
  for (const auto& m : list) names.push_back(m.name);
  return names;
}

class AlignCommand : public Command {
 public:
  std::string name() const override { return "align"; }
  std::string summary() const override { return "Join presses with recordings per material and cut the model's windows"; }

  void declare(CLI::App& app) override {
    app.add_option("--recordings", options_.recordings, "Recordings file (haptex convert)")->required();
    app.add_option("--gelsight", options_.gelsight, "GelSight file (haptex capture extract)")->required();
    add_output_options(app, options_.output, options_.overwrite, "Dataset file to write (HDF5)");
    app.add_option("--stride", options_.stride, "Samples between window starts")->capture_default_str()->check(CLI::Range(1, 100000));
    app.add_option("--names", options_.names_file, "JSON map {\"gelsight name\": \"recordings name\"} for names that differ");
  }

  int run(const GlobalOptions& global) override {
    refuse_output_among_inputs(options_.output, {options_.recordings, options_.gelsight});
    options_.provenance = global.command_line;
    const auto start = std::chrono::steady_clock::now();
    const align::AlignResult r = align::align_dataset(options_, terminal_progress(global, "align"));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const auto only_r = names_of(r.match.only_recordings), only_g = names_of(r.match.only_gelsight);
    if (global.json) {
      std::cout << nlohmann::json{{"output", options_.output}, {"materials", r.match.pairs.size()},
                                  {"recordings", r.recordings}, {"presses", r.presses}, {"windows", r.windows},
                                  {"only_recordings", only_r}, {"only_gelsight", only_g}, {"notes", r.notes},
                                  {"seconds", seconds}}.dump(2) << "\n";
      return 0;
    }
    if (global.quiet) return 0;
    std::cout << "wrote " << text::printable(options_.output) << ": " << r.match.pairs.size() << " materials, " << r.recordings
              << " recordings, " << r.presses << " presses, " << r.windows << " windows, in " << seconds << " s\n";
    auto list = [](const char* label, const std::vector<std::string>& names) {
      if (names.empty()) return;
      std::cout << label;
      for (const auto& n : names) std::cout << " '" << text::printable(n) << "'";
      std::cout << "\n";
    };
    list("only in the recordings file (left out):", only_r);
    list("only in the gelsight file (left out):", only_g);
    for (const auto& note : r.notes) std::cout << "note: " << text::printable(note) << "\n";
    return 0;
  }

 private:
  align::AlignOptions options_;
};

}  // namespace

std::unique_ptr<Command> make_align_command() { return std::make_unique<AlignCommand>(); }

}  // namespace haptex::apps
