// haptex split dataset.h5 -o split.json [--sections 25] [--val 3] [--test 3] [--seed 0] [--min-coverage 0.9]
#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <optional>

#include "apps/output_options.hpp"
#include "apps/command.hpp"
#include "apps/number_checks.hpp"
#include "core/durable_file.hpp"
#include "core/output_set.hpp"
#include "core/error.hpp"
#include "core/owned_folder.hpp"
#include "core/partial_directory.hpp"
#include "core/output_is_input.hpp"
#include "core/json/schema.hpp"
#include "core/text/utf8.hpp"
#include "evaluate/measures/summary_statistics.hpp"
#include "split/split_manifest.hpp"
#include "split/split_plots.hpp"
#include "qa/integrity.hpp"
#include "qa/sound_split.hpp"

namespace haptex::apps {
namespace {

class SplitCommand : public Command {
 public:
  std::string name() const override { return "split"; }
  std::string summary() const override { return "Cut leakage-free train/val/test sets whose force-speed ranges overlap"; }

  void declare(CLI::App& app) override {
    app.add_option("dataset", dataset_, "Dataset file (haptex align)")->required();
    add_output_options(app, output_, force_, "Split manifest to write (JSON)");
    app.add_option("--sections", options_.sections, "Sections per recording")->capture_default_str()->check(CLI::Range(3, 10000));
    app.add_option("--val", options_.val, "Validation sections")->capture_default_str()->check(CLI::Range(1, 10000));
    app.add_option("--test", options_.test, "Test sections")->capture_default_str()->check(CLI::Range(1, 10000));
    app.add_option("--seed", options_.seed, "Random seed")->check(seed_number())->capture_default_str();
    app.add_option("--min-coverage", options_.min_coverage, "Least share of val/test windows inside the training hull")
        ->capture_default_str()->check(CLI::Range(0.0, 1.0));
    app.add_option("--tries", options_.tries, "Assignments tried per material")->capture_default_str()->check(CLI::Range(1, 1000000));
    app.add_flag("--no-plots", no_plots_, "Do not write the per-material plots");
  }

  int run(const GlobalOptions& global) override {
    if (!no_plots_ && same_output_path(output_, plots_folder()))
      throw input_error(output_, "", "names the plot folder (<output>.plots) itself", "Give the manifest a name ending in .json");
    refuse_output_among_inputs(output_, {dataset_});
    refuse_output_among_inputs(plots_folder(), {dataset_});
    json::check_replaceable_json(output_, force_, split::kManifestFormat);
    // The plots go with the manifest --force replaces only while it is there and their list names it
    // back (review 33, F1: the plots of a manifest moved away, or another manifest's, went).
    std::error_code ec;
    const bool manifest_there = std::filesystem::is_regular_file(output_, ec);
    const auto split_folder = [&](const std::string& dir) {
      return manifest_there && is_haptex_folder(dir, "haptex split") && same_output_path(folder_owner(dir), output_);
    };
    if (no_plots_ && force_)
      EarlierOutput::require_retirable(plots_folder(), split_folder, "the plot folder",
                                       "Move your files out of it (or the folder away), or run without --no-plots");
    // The plots go into a folder written whole (refused now, before any work, when it may not be replaced).
    std::optional<PartialDirectory> plots_dir;
    if (!no_plots_) {
      plots_dir.emplace(plots_folder(), FolderOptions{force_, "plot folder", "-o", "haptex split"});
      plots_dir->belongs_to(output_);
    }
    qa::require_sound_dataset(dataset_);
    const auto windows = split::read_dataset_windows(dataset_);
    const auto splits = split::search_split(windows, options_, dataset_);
    const nlohmann::json manifest = split::manifest_json(dataset_, options_, splits, global.command_line);
    qa::require_sound_split({output_, manifest}, dataset_, qa::Manifest::about_to_be_written);
    split::PlotResult plots;
    if (plots_dir)
      plots_dir->fill([&](const std::string& dir) {
        plots = split::write_split_plots(dataset_, windows, splits, options_.sections, dir, plots_folder());
      });
    // The manifest and its plots appear together or not at all (a full disk while writing either, a
    // folder appearing at the plots' name). --force --no-plots: plots an earlier split wrote describe
    // the manifest replaced, so they go too; a folder of that name holding anything else stays.
    PartialFile manifest_file(output_, force_, [](const std::string& p) { json::check_replaceable_json(p, true, split::kManifestFormat); });
    json::write_file(manifest, "split.schema.json", manifest_file);
    EarlierOutput earlier_plots(plots_folder(), split_folder);
    commit_together({&manifest_file, plots_dir ? &*plots_dir : nullptr, !plots_dir && force_ ? &earlier_plots : nullptr});
    if (global.json) {
      std::cout << json::read_file(output_).dump(2) << "\n";
      return 0;
    }
    if (!global.quiet) print(splits, plots);
    return 0;
  }

 private:
  std::string plots_folder() const { return std::filesystem::path(output_).replace_extension(".plots").string(); }

  void print(const std::vector<split::MaterialSplit>& splits, const split::PlotResult& plots) const {
    std::vector<double> worst;
    for (const auto& s : splits) worst.push_back(s.worst());
    std::sort(worst.begin(), worst.end());
    std::cout << "wrote " << text::printable(output_) << ": " << splits.size() << " materials; worst-case coverage min "
              << std::setprecision(3) << worst.front() << ", median " << evaluate::percentile(worst, 50) << ", max " << worst.back() << "\n";
    for (const auto& s : splits)
      std::cout << "  " << std::left << std::setw(24) << s.id << std::right << " windows " << s.train_windows << "/"
                << s.val_windows << "/" << s.test_windows << "  coverage val " << std::setprecision(3) << s.val_coverage
                << " test " << s.test_coverage << "\n";
    if (!plots.images.empty()) std::cout << plots.images.size() << " plots in " << text::printable(std::filesystem::path(plots.images[0]).parent_path().string()) << "\n";
    if (!plots.note.empty()) std::cout << "note: " << text::printable(plots.note) << "\n";
  }

  std::string dataset_, output_;
  split::SplitOptions options_;
  bool no_plots_ = false, force_ = false;
};

}  // namespace

std::unique_ptr<Command> make_split_command() { return std::make_unique<SplitCommand>(); }

}  // namespace haptex::apps
