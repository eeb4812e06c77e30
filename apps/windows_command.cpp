// haptex windows dataset.h5 --split split.json -o windows.h5 [--force]: the evaluation's grid of the
// test sections, for models trained outside haptex (docs/windows.md).
#include <iostream>
#include <nlohmann/json.hpp>

#include "apps/dataset_split_input.hpp"
#include "apps/output_options.hpp"
#include "apps/command.hpp"
#include "core/durable_file.hpp"
#include "core/output_is_input.hpp"
#include "core/text/utf8.hpp"
#include "dataset/windows_file.hpp"
#include "evaluate/inputs/evaluation_grid.hpp"

namespace haptex::apps {
namespace {

class WindowsCommand : public Command {
 public:
  std::string name() const override { return "windows"; }
  std::string summary() const override { return "Write the evaluation's test windows (actions, presses, spectra) for models trained elsewhere"; }

  void declare(CLI::App& app) override {
    input_.declare(app);
    add_output_options(app, output_, force_, "Windows file to write (HDF5)");
  }

  int run(const GlobalOptions& global) override {
    refuse_output_among_inputs(output_, input_.files());
    check_output_path(output_, force_);
    const split::DatasetSplit split = input_.read();
    const evaluate::EvaluationGrid grid = evaluate::evaluation_grid(split, evaluate::read_section_signals(split));
    dataset::write_windows_file({grid.windows, grid.section, grid.press, split.dataset_path, grid.dataset_sha256, split.manifest_path,
                                 grid.split_sha256},
                                output_, force_, global.command_line);
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
      std::cout << "wrote " << text::printable(output_) << " (" << grid.windows.size() << " test windows of " << materials << " materials)\n";
  }

  DatasetSplitInput input_;
  std::string output_;
  bool force_ = false;
};

}  // namespace

std::unique_ptr<Command> make_windows_command() { return std::make_unique<WindowsCommand>(); }

}  // namespace haptex::apps
