// haptex windows dataset.h5 --split split.json -o windows.h5 [--force]: the evaluation's grid of the
// test sections, for models trained outside haptex (docs/windows.md).
#include <iostream>
#include <nlohmann/json.hpp>

#include "apps/command.hpp"
#include "core/durable_file.hpp"
#include "core/output_is_input.hpp"
#include "evaluate/evaluation_grid.hpp"
#include "qa/sound_split.hpp"
#include "split/manifest_reader.hpp"

namespace haptex::apps {
namespace {

class WindowsCommand : public Command {
 public:
  std::string name() const override { return "windows"; }
  std::string summary() const override { return "Write the evaluation's test windows (actions, presses, spectra) for models trained elsewhere"; }

  void declare(CLI::App& app) override {
    app.add_option("dataset", dataset_, "Dataset file (haptex align)")->required();
    app.add_option("--split", split_, "Split manifest (haptex split) made from this dataset")->required();
    app.add_option("-o,--output", output_, "Windows file to write (HDF5)")->required();
    app.add_flag("--force", force_, "Replace the output file if it exists");
  }

  int run(const GlobalOptions& global) override {
    refuse_output_among_inputs(output_, {dataset_, split_});
    check_output_path(output_, force_);
    const split::DatasetSplit split = split::read_dataset_split(dataset_, split_);
    qa::require_sound_split(split::read_split_manifest(split_), dataset_);
    const evaluate::EvaluationGrid grid = evaluate::evaluation_grid(split, evaluate::read_section_signals(split));
    evaluate::write_windows_file(grid, split, output_, force_, global.command_line);
    print(grid, global);
    return 0;
  }

 private:
  void print(const evaluate::EvaluationGrid& grid, const GlobalOptions& global) const {
    const std::size_t materials = grid.windows.materials.size();
    if (global.json)
      std::cout << nlohmann::json{{"output", output_}, {"windows", grid.windows.size()}, {"materials", materials},
                                  {"dataset_sha256", grid.dataset_sha256}, {"split_sha256", grid.split_sha256}}.dump(2)
                << "\n";
    else if (!global.quiet)
      std::cout << "wrote " << output_ << " (" << grid.windows.size() << " test windows of " << materials << " materials)\n";
  }

  std::string dataset_, split_, output_;
  bool force_ = false;
};

}  // namespace

std::unique_ptr<Command> make_windows_command() { return std::make_unique<WindowsCommand>(); }

}  // namespace haptex::apps
