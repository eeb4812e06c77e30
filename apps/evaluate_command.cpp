// haptex evaluate dataset.h5 --split split.json --model model.h5 [--model ...] [--predictions NAME=preds.h5 ...]
//                [--baseline ar-refit|hatt-published]
//                [--hatt-models DIR] [--reconstruct fgla|online|noise|none] [--repeats 10] -o report/
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>

#include "apps/input_file_option.hpp"
#include "apps/dataset_split_input.hpp"
#include "apps/output_options.hpp"
#include "apps/command.hpp"
#include "apps/number_checks.hpp"
#include "apps/terminal_progress.hpp"
#include "core/error.hpp"
#include "core/output_is_input.hpp"
#include "core/text/format.hpp"
#include "core/text/utf8.hpp"
#include "evaluate/report/report_writer.hpp"
#include "evaluate/run_evaluation.hpp"
#include "evaluate/floors/truth_comparison.hpp"
#include "predict/model_file.hpp"
#include "render/reconstruction.hpp"
#include "dataset/truth_file.hpp"

namespace haptex::apps {
namespace {

class EvaluateCommand : public Command {
 public:
  std::string name() const override { return "evaluate"; }
  std::string summary() const override { return "Compare trained models with an AR baseline on the test sections; write a report"; }

  void declare(CLI::App& app) override {
    input_.declare(app, "Split manifest the models were trained with");
    app.add_option("--model", models_, "Model file (haptex train); repeat for several (unified sizes, per-material)");
    app.add_option("--predictions", predictions_,
                   "NAME=FILE: predictions of a model trained elsewhere on the grid of `haptex windows` (docs/benchmark.md); "
                   "repeat for several. At least one --model or --predictions");
    const std::map<std::string, evaluate::Baseline> baselines{{"ar-refit", evaluate::Baseline::ar_refit},
                                                              {"hatt-published", evaluate::Baseline::hatt_published}};
    app.add_option("--baseline", options_.baseline, "ar-refit (fitted here from train+val) or hatt-published (--hatt-models)")
        ->transform(CLI::CheckedTransformer(baselines, CLI::ignore_case))->capture_default_str();
    app.add_option("--hatt-models", options_.hatt_models, "Folder of the HaTT model XMLs for hatt-published")->check(CLI::ExistingDirectory);
    app.add_option("--reconstruct", reconstruct_, "Phase reconstruction of the stitched-signal experiment")
        ->transform(CLI::IsMember({"fgla", "online", "noise", "none"}, CLI::ignore_case))->capture_default_str();
    app.add_option("--repeats", options_.repeats, "Baseline renderings (seeds) per test section")->capture_default_str()->check(CLI::Range(2, 1000));
    app.add_option("--seed", options_.seed, "Random seed of the renderings and of FGLA's initial phase")->check(seed_number())->capture_default_str();
    app.add_option("--threads", options_.threads, "Threads (0: every core)")->capture_default_str();
    app.add_option("--truth", options_.truth,
                   "truth.h5 of haptex synth hatt or synth materials: the oracle noise floor (and, for synth materials, "
                   "the models against the noise-free spectra grid)")
        ->check(input_file());
    add_output_options(app, output_, force_, "Report folder to write");
  }

  int run(const GlobalOptions& global) override {
    // --reconstruct none leaves the stitched-signal experiment out.
    if (reconstruct_ == "none")
      options_.reconstruct.reset();
    else
      options_.reconstruct = render::parse_reconstruction(reconstruct_);
    if (options_.baseline == evaluate::Baseline::hatt_published && options_.hatt_models.empty())
      throw Error(Error::Kind::bad_input, "evaluate: --baseline hatt-published needs --hatt-models DIR (the toolkit's Models_*.xml)");
    if (options_.baseline != evaluate::Baseline::hatt_published && !options_.hatt_models.empty())
      throw Error(Error::Kind::bad_input,
                  "evaluate: --hatt-models is read only by --baseline hatt-published (the baseline now is ar-refit, fitted "
                  "from train+val); add --baseline hatt-published, or drop --hatt-models");
    for (const std::string& argument : predictions_) options_.predictions.push_back(evaluate::parse_predictions_argument(argument));
    std::vector<std::string> inputs = models_;
    for (const evaluate::PredictionsInput& p : options_.predictions) inputs.push_back(p.path);
    inputs.insert(inputs.end(), {input_.dataset, input_.split, options_.truth, options_.hatt_models});
    refuse_output_among_inputs(output_, inputs);
    if (std::filesystem::exists(output_) && !force_)
      throw input_error(output_, "", "the report folder exists", "Choose another -o or add --force");
    evaluate::check_report_folder(output_, force_);  // before any work: a report it could not write (review 14, F3)
    const split::DatasetSplit split = input_.read();
    std::vector<evaluate::ModelInput> models;
    for (const std::string& path : models_)
      models.push_back({path, std::filesystem::path(path).filename().string(), predict::read_model(path)});
    evaluate::Evaluation e = evaluate::run_evaluation(split, models, options_, terminal_progress(global, "evaluate"));
    if (!options_.truth.empty() && has_grid(dataset::read_truth_file(options_.truth)))
      for (const evaluate::ModelInput& m : models) e.notes.push_back(truth_note(m));
    const evaluate::ReportFiles files = evaluate::write_report(e, output_, force_);
    if (global.json) {
      std::cout << files.results_json_text << "\n";
      return 0;
    }
    if (global.quiet) return 0;
    std::cout << "wrote " << text::printable(files.report) << " (" << e.experiments.size() << " experiments, " << std::fixed << std::setprecision(1)
              << e.seconds << " s)\n";
    for (const evaluate::Experiment& x : e.experiments) {
      std::cout << text::format("  %s: better than the %s on %zu of %zu materials, significantly on %zu, significantly worse on %zu (mean distance %.4g vs %.4g m/s^2)\n",
                  x.id.c_str(), x.baseline_label.substr(0, x.baseline_label.find(" (")).c_str(), x.better(), x.materials.size(),
                  x.significantly_better(), x.significantly_worse(), x.mean_model(), x.mean_baseline());
      if (std::isfinite(x.median_floor_ratio()))
        std::cout << text::format("  %s: within 10 %% of the %s on %zu of %zu materials (median ratio %.3g, worst %.3g)%s\n", x.id.c_str(),
                    e.floor_kind == "oracle" ? "floor (oracle where --truth knows the material)" : "floor estimate", x.within_floor(0.10), x.materials.size(),
                    x.median_floor_ratio(), x.worst_floor_ratio(), x.below_floor() ? "; BEATS THE ORACLE: the oracle is wrong" : "");
    }
    if (!files.note.empty()) std::cout << "note: " << text::printable(files.note) << "\n";
    return 0;
  }

 private:
  static bool has_grid(const dataset::Truth& truth) {
    return std::any_of(truth.materials.begin(), truth.materials.end(), [](const dataset::MaterialTruth& m) { return m.grid.has_value(); });
  }

  std::string truth_note(const evaluate::ModelInput& m) const {
    const std::string& truth_ = options_.truth;
    const auto found = evaluate::compare_with_truth(m.model, truth_);
    const evaluate::TruthComparison all = evaluate::overall(found);
    if (all.points == 0) return m.label + ": no point of " + truth_ + " lies inside the training range";
    return text::format(
                  "%s against the noise-free spectra of %s (%zu materials, %zu speed-force points inside the training range): "
                  "mean distance %.4g m/s^2; a constant spectrum per material (the truth's own mean) %.4g; mean true spectrum norm %.4g",
                  m.label.c_str(), truth_.c_str(), found.size(), all.points, all.model, all.constant, all.truth_norm);
  }

  DatasetSplitInput input_;
  std::string output_, reconstruct_ = "fgla";
  std::vector<std::string> models_, predictions_;
  evaluate::EvaluationOptions options_;
  bool force_ = false;
};

}  // namespace

std::unique_ptr<Command> make_evaluate_command() { return std::make_unique<EvaluateCommand>(); }

}  // namespace haptex::apps
