// haptex synth hatt | materials: the toolkit's own data, deterministic for a seed.
#include <chrono>
#include <iostream>
#include <nlohmann/json.hpp>

#include "apps/output_options.hpp"
#include "apps/command.hpp"
#include "apps/number_checks.hpp"
#include "apps/terminal_progress.hpp"
#include "core/error.hpp"
#include "core/text/parse_number.hpp"
#include "core/text/utf8.hpp"
#include "synth/synth_runs.hpp"

namespace haptex::apps {
namespace {

// What --force may replace (core/owned_folder.hpp).
std::pair<int, int> parse_size(const std::string& text) {
  const std::optional<text::FrameSize> size = text::parse_frame_size(text);
  if (!size || size->width < 64 || size->height < 48 || size->width > 4096 || size->height > 4096)
    throw input_error("--size", text, "not a frame size from 64x48 to 4096x4096", "Write WIDTHxHEIGHT, e.g. 960x720");
  return {int(size->width), int(size->height)};
}

class SynthCommand : public Command {
 public:
  std::string name() const override { return "synth"; }
  std::string summary() const override { return "Make synthetic recordings and GelSight presses (HaTT-model-driven or procedural)"; }

  void declare(CLI::App& app) override {
    app.require_subcommand(1);
    hatt_ = app.add_subcommand("hatt", "Render recordings from published HaTT model files (and presses from their photographs)");
    hatt_->add_option("--models", hatt_options_.models_dir, "Folder of Models_<Material>.xml")->required();
    hatt_->add_option("--images", hatt_options_.images_dir, "Folder of <Material>_square.jpg photographs (optional)");
    add_output_options(*hatt_, hatt_options_.out, hatt_options_.overwrite, "Output folder");
    hatt_->add_option("--recordings", hatt_options_.recordings, "Recordings per material")->capture_default_str()->check(CLI::Range(1, 100));
    hatt_->add_option("--seconds", hatt_options_.seconds, "Seconds per recording")->capture_default_str()->check(CLI::Range(0.2, 600.0));
    hatt_->add_option("--seed", hatt_options_.seed, "Random seed")->check(seed_number())->capture_default_str();

    materials_ = app.add_subcommand("materials", "Procedural materials: height fields -> presses, recordings, truth spectra");
    materials_->add_option("-n", materials_options_.count, "Number of materials (default: the 8-material demo set)")
        ->capture_default_str()->check(CLI::Range(1, 10000));
    add_output_options(*materials_, materials_options_.out, materials_options_.overwrite, "Output folder");
    materials_->add_option("--recordings", materials_options_.recordings, "Recordings per material")->capture_default_str()->check(CLI::Range(1, 100));
    materials_->add_option("--presses", materials_options_.presses, "Presses per material")->capture_default_str()->check(CLI::Range(1, 100));
    materials_->add_option("--seconds", materials_options_.seconds, "Seconds per recording")->capture_default_str()->check(CLI::Range(0.2, 600.0));
    materials_->add_option("--size", size_, "GelSight frame size WIDTHxHEIGHT")->capture_default_str();
    materials_->add_option("--seed", materials_options_.seed, "Random seed")->check(seed_number())->capture_default_str();
  }

  int run(const GlobalOptions& global) override {
    const auto start = std::chrono::steady_clock::now();
    synth::SynthSummary summary;
    std::string out;
    if (hatt_->parsed()) {
      hatt_options_.provenance = global.command_line;
      summary = synth::synth_hatt(hatt_options_, terminal_progress(global, "synth hatt"));
      out = hatt_options_.out;
    } else {
      std::tie(materials_options_.width, materials_options_.height) = parse_size(size_);
      materials_options_.provenance = global.command_line;
      summary = synth::synth_materials(materials_options_, terminal_progress(global, "synth materials"));
      out = materials_options_.out;
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    print(summary, out, seconds, global);
    return 0;
  }

 private:
  static void print(const synth::SynthSummary& s, const std::string& out, double seconds, const GlobalOptions& global) {
    if (global.json) {
      std::cout << nlohmann::json{{"output", out}, {"materials", s.materials}, {"recordings", s.recordings},
                                  {"presses", s.presses}, {"materials_without_images", s.materials_without_images},
                                  {"seconds", seconds}}.dump(2) << "\n";
      return;
    }
    if (global.quiet) return;
    std::cout << "wrote " << text::printable(out) << ": " << s.materials.size() << " materials, " << s.recordings << " recordings, "
              << s.presses << " press videos, in " << seconds << " s\n";
    if (!s.materials_without_images.empty())
      std::cout << "no photograph (so no presses) for " << s.materials_without_images.size() << " materials\n";
  }

  CLI::App* hatt_ = nullptr;
  CLI::App* materials_ = nullptr;
  synth::SynthHattOptions hatt_options_;
  synth::SynthMaterialsOptions materials_options_;
  std::string size_ = "960x720";
};

}  // namespace

std::unique_ptr<Command> make_synth_command() { return std::make_unique<SynthCommand>(); }

}  // namespace haptex::apps
