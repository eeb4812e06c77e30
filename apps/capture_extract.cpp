// haptex capture extract <press files | videos | folder per material | folder of those> -o gelsight.h5
// Per press: the peak frame and its neighbours, the reference, the score curve; and a contact sheet PNG.
#include <cmath>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>

#include "apps/output_options.hpp"
#include "apps/capture_subcommands.hpp"
#include "apps/number_checks.hpp"
#include "core/output_is_input.hpp"
#include "apps/terminal_progress.hpp"
#include "capture/extraction/extract_presses.hpp"
#include "core/text/utf8.hpp"

namespace haptex::apps {
namespace {

class CaptureExtract : public CaptureSubcommand {
 public:
  CLI::App* declare(CLI::App& capture) override {
    CLI::App* app = capture.add_subcommand("extract", "Press files or videos -> gelsight.h5 (peak frames) and contact sheets");
    app->add_option("inputs", inputs_, "Press files, videos, a folder per material, or a folder of such folders")->required();
    add_output_options(*app, output_, options_.overwrite, "GelSight file to write (HDF5)");
    app->add_option("--reference", reference_, "A no-contact image of the sensor, instead of each video's leading frames");
    app->add_option("--material", material_, "Material name for every input (default: the folder's name)");
    app->add_option("--reference-frames", options_.settings.reference_frames, "Leading no-contact frames averaged (10 to 250)")
        ->capture_default_str();
    app->add_option("--frames-per-press", options_.settings.frames_per_press, "The peak and its neighbours kept")
        ->capture_default_str()
        ->check(CLI::Range(1, 100));
    app->add_option("--pixel-threshold", pixel_threshold_,
                    "Least per-pixel change that counts, in grey levels (default: the noise of the footage's own "
                    "no-contact frames; with --reference, 6 for lossy sources, 1 for lossless)")
        ->check(non_negative_number())
        ->check(CLI::Range(0.0, 255.0));  // an 8-bit grey level changes by at most 255
    app->add_option("--trigger", trigger_,
                    "Least contact score that starts a press (default: from the footage's own no-contact frames; with "
                    "--reference, 0.25 lossy, 0.02 lossless)")
        ->check(positive_number());
    app->add_option("--sheets", options_.sheets_dir, "Folder for the contact sheets (default: <output>_sheets)");
    app->add_flag("--no-sheets", no_sheets_, "Write no contact sheets");
    app->add_flag("--explain", options_.explain,
                  "Chart each source's score over time (reference frames, thresholds, presses) in <output>_explain/, "
                  "also when no press is found");
    return app;
  }

  int run(const GlobalOptions& global) override {
    if (!reference_.empty()) options_.reference_path = reference_;
    std::vector<std::string> inputs = inputs_;
    inputs.push_back(reference_);
    refuse_output_among_inputs(output_, inputs);
    refuse_output_among_inputs(options_.sheets_dir.empty() ? capture::default_sheets_dir(output_) : options_.sheets_dir, inputs);
    if (!options_.sheets_dir.empty() && same_output_path(options_.sheets_dir, output_))
      throw input_error("--sheets", options_.sheets_dir, "is the output file itself", "Give the contact sheets another folder");
    if (options_.explain) {
      const std::string explain = capture::default_explain_dir(output_);
      refuse_output_among_inputs(explain, inputs);
      if (!options_.sheets_dir.empty() && same_output_path(options_.sheets_dir, explain))
        throw input_error("--sheets", options_.sheets_dir, "is the --explain folder", "Give the contact sheets another folder");
    }
    if (!material_.empty()) options_.material = material_;
    if (pixel_threshold_) options_.settings.pixel_threshold = *pixel_threshold_;
    if (trigger_) options_.settings.trigger = *trigger_;
    options_.sheets = !no_sheets_;
    options_.provenance = global.command_line;
    try {
      print(capture::extract_presses(inputs_, output_, options_, terminal_progress(global, "extract")), global);
    } catch (const capture::NoPressFound& e) {
      if (global.json) print_json(e.result(), false);  // what each source was judged by, then the error
      throw;
    }
    return 0;
  }

 private:
  // written: false when no input held a press (the output and the sheets are null).
  void print_json(const capture::ExtractResult& r, bool written) const {
    nlohmann::json presses = nlohmann::json::array();
    for (const auto& p : r.presses)
      presses.push_back({{"material", p.material}, {"material_id", p.material_id}, {"press", p.press},
                         {"source", p.source}, {"press_in_source", p.press_in_source}, {"frame_start", p.frame_start},
                         {"frame_end", p.frame_end}, {"contact_first", p.contact_first},
                         {"contact_last", p.contact_last}, {"peak_index", p.peak_index}, {"peak_score", p.peak_score},
                         {"contact_sheet", p.contact_sheet}});
    nlohmann::json detections = nlohmann::json::array();
    for (const auto& d : r.detections) {
      const float snr = d.signal_to_noise();
      detections.push_back({{"source", d.source}, {"reference", d.reference},
                            {"reference_kind", d.reference_kind}, {"presses", d.presses},
                            {"chart", d.chart.empty() ? nlohmann::json() : nlohmann::json(d.chart)},
                            {"noise", d.noise}, {"pixel_threshold", d.pixel_threshold}, {"no_contact_level", d.level}, {"jitter", d.jitter},
                            {"trigger", d.trigger}, {"release", d.release}, {"highest_score", d.highest_score},
                            {"highest_frame", d.highest_frame}, {"presses_left_out", d.presses_left_out},
                            {"signal_to_noise", std::isfinite(snr) ? nlohmann::json(snr) : nlohmann::json()}});
    }
    std::cout << nlohmann::json{{"output", written ? nlohmann::json(output_) : nlohmann::json()}, {"presses", presses},
                                {"detection", detections}, {"sources", r.sources},
                                {"sources_without_press", r.sources_without_press}, {"frames_scored", r.frames_scored},
                                {"frames_unreadable", r.frames_unreadable},
                                {"sheets", written ? nlohmann::json(r.sheets_dir) : nlohmann::json()},
                                {"explain", r.explain_dir.empty() ? nlohmann::json() : nlohmann::json(r.explain_dir)}}
                     .dump(2)
              << "\n";
  }

  void print(const capture::ExtractResult& r, const GlobalOptions& global) const {
    if (global.json) return print_json(r, true);
    if (global.quiet) return;
    for (const auto& d : r.detections)
      if (d.presses == 0) std::cerr << "haptex capture: warning: " << text::printable(d.source) << ": no press found: " << capture::describe(d) << "\n";
    if (global.verbose)
      for (const auto& d : r.detections)
        std::cerr << text::printable(d.source) << ": " << d.presses << " presses; " << capture::describe(d) << "\n";
    if (global.verbose)
      for (const auto& p : r.presses)
        std::cerr << text::printable(p.source) << " -> /materials/" << p.material_id << "/presses/" << p.press << ": frames "
                  << p.frame_start << "-" << p.frame_end << ", contact " << p.contact_first << "-" << p.contact_last
                  << ", peak " << p.peak_index << " (score " << p.peak_score << ")\n";
    std::set<std::string> materials;
    for (const auto& p : r.presses) materials.insert(p.material_id);
    std::cout << "wrote " << text::printable(output_) << ": " << r.presses.size() << " presses of " << materials.size()
              << " materials from " << r.sources << " files";
    if (!r.sheets_dir.empty()) std::cout << "; contact sheets in " << text::printable(r.sheets_dir);
    if (!r.explain_dir.empty()) std::cout << "; score charts in " << text::printable(r.explain_dir);
    std::cout << "\n";
    if (r.frames_unreadable > 0)
      std::cout << r.frames_unreadable << " frames did not decode (damaged, or announced by a video cut short); none was "
                << "taken as a peak or kept\n";
  }

  std::vector<std::string> inputs_;
  std::string output_, reference_, material_;
  bool no_sheets_ = false;
  std::optional<float> pixel_threshold_, trigger_;  // unset: the footage's own (or the image floors)
  capture::ExtractOptions options_;
};

}  // namespace

std::unique_ptr<CaptureSubcommand> make_capture_extract() { return std::make_unique<CaptureExtract>(); }

}  // namespace haptex::apps
