// haptex trajectory recordings.h5|dataset.h5 --material ID [--recording K] [--start S] [--seconds T] -o traj.csv [--force]
// A recorded stroke's low-passed force and speed as the trajectory CSV that render and play read
// (docs/render.md, "A trajectory to start from").
#include <iostream>
#include <nlohmann/json.hpp>

#include "apps/command.hpp"
#include "apps/number_checks.hpp"
#include "apps/output_options.hpp"
#include "core/durable_file.hpp"
#include "core/output_is_input.hpp"
#include "core/text/format.hpp"
#include "core/text/utf8.hpp"
#include "dataset/window.hpp"
#include "predict/recorded_trajectory.hpp"
#include "qa/integrity.hpp"

namespace haptex::apps {
namespace {

class TrajectoryCommand : public Command {
 public:
  std::string name() const override { return "trajectory"; }
  std::string summary() const override { return "Write a recorded stroke's force and speed as the trajectory CSV render and play read"; }

  void declare(CLI::App& app) override {
    app.add_option("input", input_, "Recordings file (haptex convert) or dataset (haptex align)")->required();
    app.add_option("--material", stretch_.material, "The material's id (haptex info lists them)")->required();
    app.add_option("--recording", stretch_.recording, "Which of its recordings (0, 1, ...)")->capture_default_str()->check(CLI::NonNegativeNumber);
    app.add_option("--start", stretch_.start_s, "From this time in the recording, in seconds")->capture_default_str()->check(non_negative_number());
    app.add_option("--seconds", stretch_.seconds, "This long (0: to the recording's end)")->capture_default_str()->check(non_negative_number());
    add_output_options(app, output_, force_, "Trajectory CSV to write (time_s,force_n,speed_mm_s at 10 kHz)");
  }

  int run(const GlobalOptions& global) override {
    refuse_output_among_inputs(output_, {input_});
    predict::check_trajectory_csv_output(output_, force_);
    const dataset::OpenedFile source = predict::open_trajectory_source(input_);
    qa::require_sound_layout(source.file.root(), source.kind);
    const predict::Trajectory t = predict::recorded_trajectory(source, stretch_);
    PartialFile out(output_, force_, [](const std::string& p) { predict::check_trajectory_csv_output(p, true); });
    write_text(out, predict::trajectory_csv_text(t));
    out.commit();
    const double seconds = double(t.force.size()) / dataset::kSampleRateHz;
    if (global.json)
      std::cout << nlohmann::json{{"output", output_}, {"samples", t.force.size()}, {"seconds", seconds}, {"material", stretch_.material},
                                  {"recording", stretch_.recording}, {"start_s", stretch_.start_s}}.dump(2)
                << "\n";
    else if (!global.quiet)
      std::cout << text::format("wrote %s: %zu samples (%.3f s) of %s recording %d from %g s\n", text::printable(output_).c_str(), t.force.size(),
                                seconds, text::printable(stretch_.material).c_str(), stretch_.recording, stretch_.start_s);
    return 0;
  }

 private:
  std::string input_, output_;
  predict::RecordedStretch stretch_;
  bool force_ = false;
};

}  // namespace

std::unique_ptr<Command> make_trajectory_command() { return std::make_unique<TrajectoryCommand>(); }

}  // namespace haptex::apps
