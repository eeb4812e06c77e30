// haptex train dataset.h5 --split split.json -o model.h5 [--per-material] [sizes] [--seed S] [--log FILE]
#include <unistd.h>

#include <chrono>
#include <optional>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>

#include "apps/dataset_split_input.hpp"
#include "apps/output_options.hpp"
#include "apps/command.hpp"
#include "apps/number_checks.hpp"
#include "apps/terminal_progress.hpp"
#include "core/h5/atomic_file.hpp"
#include "core/output_is_input.hpp"
#include "core/durable_file.hpp"
#include "core/output_set.hpp"
#include "core/error.hpp"
#include "core/h5/file.hpp"
#include "core/json/schema.hpp"
#include "core/sha256.hpp"
#include "core/text/utf8.hpp"
#include "core/version.hpp"
#include "dataset/format.hpp"
#include "predict/model_file.hpp"
#include "predict/train.hpp"

namespace haptex::apps {
namespace {

nlohmann::json epoch_json(const predict::EpochReport& r) {
  nlohmann::json e = {{"stage", r.stage}, {"epoch", r.epoch}, {"train_loss", r.train_loss}, {"val_loss", r.val_loss},
                      {"best", r.best}, {"seconds", r.seconds}};
  if (r.val_accuracy >= 0) e["val_accuracy"] = r.val_accuracy;
  if (r.val_weighted >= 0) e["val_weighted"] = r.val_weighted;
  return e;
}

std::size_t parameters(const predict::Model& m) {
  std::size_t n = m.texture.layers.empty() ? 0 : m.texture.parameters() + m.classifier.parameters();
  for (const auto& net : m.nets) n += net.action.parameters() + net.predictor.parameters();
  return n;
}

class TrainCommand : public Command {
 public:
  std::string name() const override { return "train"; }
  std::string summary() const override { return "Train the action-conditional spectrum model on a dataset and its split"; }

  void declare(CLI::App& app) override {
    input_.declare(app);
    add_output_options(app, output_, force_, "Model file to write (HDF5)");
    app.add_option("--log", log_, "Training log to write (JSON); default: the model's name with .training.json");
    app.add_flag("--per-material", per_material_, "One action encoder and predictor per material, no texture encoder");
    app.add_option("--latent", options_.latent, "Texture latent size")->capture_default_str()->check(CLI::Range(1, 4096));
    app.add_option("--texture-hidden", options_.texture_hidden, "Texture encoder hidden units")->capture_default_str()->check(CLI::Range(1, 4096));
    app.add_option("--action-hidden", options_.action_hidden, "Action encoder units per layer")->capture_default_str()->check(CLI::Range(1, 4096));
    app.add_option("--action-layers", options_.action_layers, "Action encoder layers")->capture_default_str()->check(CLI::Range(1, 8));
    app.add_option("--hidden", options_.predictor_hidden, "Predictor hidden units per layer")->capture_default_str()->check(CLI::Range(1, 4096));
    app.add_option("--hidden-layers", options_.predictor_layers, "Predictor hidden layers")->capture_default_str()->check(CLI::Range(0, 8));
    app.add_option("--epochs", options_.max_epochs, "Most epochs of stage 2 (unified)")->capture_default_str()->check(CLI::Range(1, 100000));
    app.add_option("--patience", options_.patience, "Epochs without a better validation loss before stopping")->capture_default_str()->check(CLI::Range(1, 100000));
    app.add_option("--batch", options_.batch, "Mini-batch size (unified)")->capture_default_str()->check(CLI::Range(1, 1 << 20));
    app.add_option("--learning-rate", options_.learning_rate, "Adam's step size")->capture_default_str()->check(CLI::Range(1e-7, 1.0));
    app.add_flag("--balance-materials,!--no-balance-materials", options_.balance_materials,
                 "Unified: weigh every material alike in the loss (default), or by its vibration level");
    app.add_option("--target-smoothing", options_.target_smoothing,
                   "Bins each training target is averaged over (odd; 1: none)")
        ->capture_default_str()->check(CLI::Range(1, 99) & odd_number());
    app.add_option("--seed", options_.seed, "Random seed (same seed, same weights)")->check(seed_number())->capture_default_str();
    app.add_option("--threads", options_.threads, "Threads (0: every core); the weights do not depend on it")->capture_default_str();
  }

  int run(const GlobalOptions& global) override {
    if (log_.empty()) log_ = default_log();
    if (same_output_path(log_, output_))
      throw input_error(log_, "", "--log names the model file itself", "Give the training log another name, or leave --log out");
    refuse_output_among_inputs(output_, input_.files());
    refuse_output_among_inputs(log_, input_.files());
    check_output_path(output_, force_);
    if (force_) h5::require_replaceable(output_, dataset::format_name(dataset::Kind::model));  // before the training, not after
    const predict::TrainingLogRecord earlier = earlier_model();
    json::check_replaceable_json(log_, force_, predict::kTrainingLogFormat);
    refuse_another_models_log();
    options_.variant = per_material_ ? predict::Variant::per_material : predict::Variant::unified;
    const auto start = std::chrono::steady_clock::now();
    const split::DatasetSplit split = input_.read();
    const Progress loading = terminal_progress(global, "texture descriptors");
    const predict::TrainingData data = predict::load_training_data(
        split, {}, [&](std::size_t done, std::size_t total) { if (loading) loading(done, total, "presses"); },
        per_material_ ? predict::PressImages::none : predict::PressImages::training);
    nlohmann::json epochs = nlohmann::json::array();
    EpochLines lines(!global.quiet && !global.json, global.verbose > 0, isatty(STDERR_FILENO));
    const predict::Model model = predict::train_model(data, options_, [&](const predict::EpochReport& r) {
      epochs.push_back(epoch_json(r));
      lines.take(r);
    });
    lines.finish();
    // The model and its log appear together or not at all (a full disk while writing either).
    h5::AtomicFile model_file(output_, force_, dataset::format_name(dataset::Kind::model));
    predict::write_model(model, model_file, global.command_line);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const nlohmann::json log = {{"format", predict::kTrainingLogFormat}, {"haptex_version", kVersion}, {"created_utc", h5::utc_now_iso8601()},
                                {"source", global.command_line}, {"model", output_}, {"model_file", relative_to_folder_of(output_, log_)},
                                {"dataset", {{"path", input_.dataset}, {"sha256", split.dataset_sha256}}},
                                {"split", {{"path", input_.split}, {"sha256", split.manifest_sha256}}},
                                {"options", options_.to_json()}, {"epochs", epochs}, {"metrics", model.metrics},
                                {"parameters", parameters(model)}, {"seconds", seconds}};
    PartialFile log_file(log_, force_, [](const std::string& p) { json::check_replaceable_json(p, true, predict::kTrainingLogFormat); });
    json::write_file(log, "training-log.schema.json", log_file);
    predict::record_training_log(model_file, output_, {log_, sha256_file(log_file.path())});
    // --force: the log the replaced model recorded (beside it, or elsewhere under --log) goes with it,
    // while it is still those bytes and names that model back; a log the model did not record stays,
    // whatever its name (review 33, F1: a log at the default name of a model moved away went).
    EarlierOutput recorded_log(earlier.log,
                               [&](const std::string& path) { return still_written(path, earlier.sha256) && describes_this_model(path); });
    commit_together({&model_file, &log_file, force_ && !earlier.log.empty() && !same_output_path(earlier.log, log_) ? &recorded_log : nullptr});
    if (global.json)
      std::cout << log.dump(2) << "\n";
    else if (!global.quiet)
      print_summary(model, seconds);
    return 0;
  }

 private:
  std::string default_log() const { return std::filesystem::path(output_).replace_extension(".training.json").string(); }

  // The training log the model at output_ names (empty when it names none, or there is no such model),
  // and its SHA-256 as written.
  predict::TrainingLogRecord earlier_model() const {
    std::error_code ec;
    if (!force_ || !std::filesystem::is_regular_file(output_, ec)) return {};
    return predict::recorded_training_log(output_).value_or(predict::TrainingLogRecord{});
  }

  // A training log haptex wrote, holding the bytes whose SHA-256 is `sha256`.
  static bool still_written(const std::string& path, const std::string& sha256) {
    try {
      json::check_replaceable_json(path, true, predict::kTrainingLogFormat);
      return sha256_file(path) == sha256;
    } catch (const std::exception&) {
      return false;
    }
  }

  // A training log haptex wrote for the model at output_: its `model_file` (relative to the log's
  // folder) is that file, however either is spelled; a log of an older haptex names it by `model`, as
  // typed. A log the model names that names another file (a copy's original, a merge's shard) is not it.
  bool describes_this_model(const std::string& path) const {
    const std::optional<std::string> model = model_of_log(path);
    return model && same_output_path(*model, output_);
  }

  // The model a training log haptex wrote names (its `model_file` resolved from the log's folder; an
  // older haptex's `model`, as typed), or nothing for any other file.
  static std::optional<std::string> model_of_log(const std::string& path) {
    try {
      json::check_replaceable_json(path, true, predict::kTrainingLogFormat);
      const nlohmann::json log = json::read_file(path);
      if (!log.is_object()) return std::nullopt;
      if (const auto file = log.find("model_file"); file != log.end() && file->is_string())
        return resolved_beside(file->get<std::string>(), path);
      if (const auto model = log.find("model"); model != log.end() && model->is_string()) return model->get<std::string>();
      return std::nullopt;
    } catch (const std::exception&) {
      return std::nullopt;
    }
  }

  // Review 31, F5: --log with --force names another model's log, that model still there: not this
  // model's to replace.
  void refuse_another_models_log() const {
    std::error_code ec;
    if (!force_ || !std::filesystem::exists(std::filesystem::symlink_status(log_, ec))) return;
    const std::optional<std::string> model = model_of_log(log_);
    if (model && !same_output_path(*model, output_) && std::filesystem::exists(std::filesystem::symlink_status(*model, ec)))
      throw input_error(log_, "", "is the training log of " + *model + ", which is still there (its model_file names it)",
                        "Give --log another name, or remove " + *model + " first");
  }

  // Which epoch lines go to stderr (docs/predict.md, "haptex train"): with -v every one; otherwise
  // stage 1's (texture, up to 80 epochs) only its last, and stage 2's every one on a terminal or, where
  // stderr is a log (Slurm, CI), one at most every 10 s and the last.
  class EpochLines {
   public:
    EpochLines(bool shown, bool verbose, bool terminal) : shown_(shown), verbose_(verbose), terminal_(terminal) {}
    void take(const predict::EpochReport& r) {
      if (!shown_) return;
      if (held_ && held_->stage == "texture" && r.stage != "texture") print_epoch(*held_);  // stage 1's last
      const auto now = std::chrono::steady_clock::now();
      const bool due = verbose_ || (r.stage != "texture" && (terminal_ || !printed_ || now - *printed_ >= std::chrono::seconds(10)));
      if (due) print_epoch(r), printed_ = now;
      held_ = due ? std::nullopt : std::optional(r);
    }
    void finish() {
      if (held_) print_epoch(*held_);
      held_.reset();
    }

   private:
    bool shown_, verbose_, terminal_;
    std::optional<predict::EpochReport> held_;  // the latest epoch not printed
    std::optional<std::chrono::steady_clock::time_point> printed_;
  };

  static void print_epoch(const predict::EpochReport& r) {
    if (r.val_accuracy >= 0)
      std::fprintf(stderr, "%-10s epoch %3d/%d  train %.4f  val %.4f  val accuracy %.3f  %6.1f s%s\n", r.stage.c_str(), r.epoch,
                   r.max_epochs, r.train_loss, r.val_loss, r.val_accuracy, r.seconds, r.best ? "  *" : "");
    else
      std::fprintf(stderr, "%-10s epoch %3d/%d  train %.5f  val %.5f m/s^2 (weighted %.5f)  %6.1f s%s\n", r.stage.c_str(), r.epoch,
                   r.max_epochs, r.train_loss, r.val_loss, r.val_weighted, r.seconds, r.best ? "  *" : "");
  }

  void print_summary(const predict::Model& m, double seconds) const {
    const auto& base = m.metrics["mean_spectrum_baseline"];
    std::cout << "wrote " << text::printable(output_) << " (" << predict::variant_name(m.variant) << ", " << m.material_ids.size() << " materials, "
              << parameters(m) << " parameters) and " << text::printable(log_) << " in " << std::fixed << std::setprecision(1) << seconds << " s\n";
    if (m.metrics.contains("texture"))
      std::cout << "texture encoder: material accuracy " << std::setprecision(3) << m.metrics["texture"]["train_accuracy"].get<double>()
                << " on training images, " << m.metrics["texture"]["val_accuracy"].get<double>() << " on the validation presses\n";
    if (m.variant == predict::Variant::unified)
      std::cout << "spectrum: validation distance " << std::setprecision(5) << m.metrics["spectrum"]["val_distance"].get<double>()
                << " m/s^2 after " << m.metrics["spectrum"]["best_epoch"].get<int>() << " epochs";
    else
      std::cout << "spectrum: " << m.nets.size() << " per-material models";
    std::cout << "; mean-spectrum baseline " << std::setprecision(5) << base["val_distance"].get<double>() << " m/s^2\n";
  }

  DatasetSplitInput input_;
  std::string output_, log_;
  predict::TrainOptions options_;
  bool per_material_ = false, force_ = false;
};

}  // namespace

std::unique_ptr<Command> make_train_command() { return std::make_unique<TrainCommand>(); }

}  // namespace haptex::apps
