// haptex merge -o OUT.h5 SHARD.h5 SHARD.h5... [--keep-first] [--force]
#include <chrono>
#include <iostream>
#include <nlohmann/json.hpp>

#include "apps/output_options.hpp"
#include "apps/command.hpp"
#include "apps/terminal_progress.hpp"
#include "core/output_is_input.hpp"
#include "core/text/utf8.hpp"
#include "merge/merge_files.hpp"

namespace haptex::apps {
namespace {

nlohmann::json plan_json(const merge::MaterialPlan& plan, const std::vector<std::string>& shards) {
  nlohmann::json materials = nlohmann::json::array(), left_out = nlohmann::json::array();
  for (const auto& m : plan.materials) materials.push_back({{"id", m.id}, {"shard", shards[m.shard]}});
  for (const auto& l : plan.left_out) left_out.push_back({{"id", l.id}, {"shard", shards[l.shard]}, {"kept_from", shards[l.kept_from]}});
  return {{"materials", materials}, {"left_out", left_out}};
}

class MergeCommand : public Command {
 public:
  std::string name() const override { return "merge"; }
  std::string summary() const override { return "Join recordings, gelsight or dataset files made on several machines into one"; }

  void declare(CLI::App& app) override {
    add_output_options(app, options_.output, options_.overwrite, "File to write, of the shards' format (HDF5)");
    app.add_option("shards", options_.shards, "Files of one format (recordings, gelsight or dataset), each with its own materials")
        ->required();
    app.add_flag("--keep-first", options_.keep_first,
                 "A material in several shards is taken from the first that has it (in the order given) instead of refused");
  }

  int run(const GlobalOptions& global) override {
    refuse_output_among_inputs(options_.output, options_.shards);
    options_.provenance = global.command_line;
    const auto start = std::chrono::steady_clock::now();
    const merge::MergeResult r = merge::merge_files(options_, terminal_progress(global, "merge"));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::string format = dataset::format_name(r.kind);
    if (global.json) {
      nlohmann::json doc = plan_json(r.plan, options_.shards);
      doc.update({{"output", options_.output}, {"format", format}, {"shards", options_.shards.size()}, {"seconds", seconds}});
      if (r.kind == dataset::Kind::dataset) doc["windows"] = r.windows;
      std::cout << doc.dump(2) << "\n";
      return 0;
    }
    if (global.quiet) return 0;
    std::cout << "wrote " << text::printable(options_.output) << " (" << format << "): " << r.plan.materials.size() << " materials from "
              << options_.shards.size() << " shards";
    if (r.kind == dataset::Kind::dataset) std::cout << ", " << r.windows << " windows";
    std::cout << ", in " << seconds << " s\n";
    for (const auto& l : r.plan.left_out)
      std::cout << "left out (--keep-first): " << l.id << " of " << text::printable(options_.shards[l.shard]) << ", taken from "
                << text::printable(options_.shards[l.kept_from]) << "\n";
    return 0;
  }

 private:
  merge::MergeOptions options_;
};

}  // namespace

std::unique_ptr<Command> make_merge_command() { return std::make_unique<MergeCommand>(); }

}  // namespace haptex::apps
