// haptex render model.h5 (--image IMG [--reference REF] | --material ID) --trajectory traj.csv -o out.wav [--csv out.csv]
//               [--reconstruct fgla|online|noise] [--iterations N] [--look-ahead F] [--live] [--full-scale A] [--seed S] [--force]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

#include "apps/input_file_option.hpp"
#include "apps/output_options.hpp"
#include "apps/command.hpp"
#include "apps/number_checks.hpp"
#include "apps/texture_options.hpp"
#include "core/durable_file.hpp"
#include "core/output_set.hpp"
#include "core/error.hpp"
#include "core/output_is_input.hpp"
#include "core/text/format.hpp"
#include "core/text/utf8.hpp"
#include "dataset/window.hpp"
#include "predict/model_file.hpp"
#include "predict/texture_choice.hpp"
#include "render/vibration_render.hpp"
#include "render/wav_writer.hpp"

namespace haptex::apps {
namespace {

class RenderCommand : public Command {
 public:
  std::string name() const override { return "render"; }
  std::string summary() const override {
    return "Render the vibration for a force/speed trajectory as a 10 kHz WAV (and CSV) for a voice-coil actuator";
  }

  void declare(CLI::App& app) override {
    app.add_option("model", model_path_, "Model file (haptex train)")->required()->check(input_file());
    add_texture_options(app, texture_);
    app.add_option("--trajectory", trajectory_path_, "Force/speed trajectory at 10 kHz: columns force, speed (time_s optional)")
        ->required()->check(input_file());
    add_output_options(app, output_, force_, "WAV file to write (mono, 10 kHz, 24-bit PCM)");
    app.add_option("--csv", csv_, "Also write the vibration as CSV: time_s, force_n, speed_mm_s, accel_m_s2");
    reconstruct_option_ = app.add_option("--reconstruct", reconstruction_,
                                       "Phase reconstruction: fgla (offline fast Griffin-Lim), online (RTISI-LA) or noise "
                                       "(white noise shaped to each frame: no phase, the surface's randomness)")
        ->capture_default_str()->check(CLI::IsMember({"fgla", "online", "noise"}));
    app.add_option("--iterations", iterations_, "fgla: iterations (default 100; 0 keeps the random initial phase); online: passes per frame (default 4)")
        ->check(CLI::Range(0, 100000));
    app.add_option("--look-ahead", look_ahead_, "online: frames of look-ahead (latency 10 ms each)")->capture_default_str()->check(CLI::Range(0, 100));
    app.add_flag("--live", live_, "Render as a live haptic loop plays it: one frame per 10 ms (online, or noise with "
                                  "--reconstruct noise), output delayed as played");
    app.add_option("--full-scale", full_scale_, "m/s^2 at WAV full scale (default: the peak, rounded up to 3 digits)")
        ->check(positive_number())
        ->check(CLI::Range(0.0, dataset::kLargestAccelerationMs2));
    app.add_flag("--steady", steady_, "online: play the predicted spectra as they are, without drawing each frame's magnitudes "
                                      "around them (steadier than any surface; docs/render.md)");
    app.add_option("--seed", seed_, "fgla: seed of the random initial phase; online: of the frames' scatter; noise: of the noise")->check(seed_number())
        ->capture_default_str();
  }

  int run(const GlobalOptions& global) override {
    const render::RenderOptions options = render_options();
    require_texture(texture_, "render");
    const std::vector<std::string> inputs{model_path_, trajectory_path_, texture_.image, texture_.reference};
    refuse_output_among_inputs(output_, inputs);
    refuse_output_among_inputs(csv_, inputs);
    render::check_wav_output(output_, force_);
    if (!csv_.empty()) {
      if (same_output_path(csv_, output_))
        throw input_error(csv_, "", "--csv and -o name the same file", "Give the CSV another name");
      render::check_vibration_csv_output(csv_, force_);
    }
    const predict::Trajectory trajectory = predict::read_trajectory(trajectory_path_);
    if (trajectory.force.size() < render::kMinTrajectorySamples)
      throw input_error(trajectory_path_, "", "fewer than " + render::min_trajectory_text(), "Give a longer trajectory");
    const predict::Model model = predict::read_model(model_path_);
    const predict::TextureCode code = predict::choose_texture(predict::Predictor(model), model_path_, texture_);

    const auto start = std::chrono::steady_clock::now();
    const render::Rendering rendering = render::render_vibration(model, code, trajectory, options);
    const double compute = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double sc = render::rendered_convergence_db(rendering), distance = render::rendered_distance(rendering);

    render::WavOptions wav;
    wav.full_scale_m_s2 = full_scale_;
    wav.overwrite = force_;
    wav.title = texture_.material.empty() ? texture_.image : texture_.material;
    wav.source = global.command_line + ", " + method(options);
    // Both outputs are written, then both committed: a full disk never leaves a WAV without its CSV.
    PartialFile wav_file(output_, force_, [](const std::string& p) { render::check_wav_output(p, true); });
    std::optional<PartialFile> csv_file;
    if (!csv_.empty()) csv_file.emplace(csv_, force_, [](const std::string& p) { render::check_vibration_csv_output(p, true); });
    const render::WavSummary written = render::write_wav(wav_file, rendering.signal, wav);
    if (csv_file) write_text(*csv_file, render::vibration_csv_text(trajectory, rendering.signal));
    commit_together({&wav_file, csv_file ? &*csv_file : nullptr});

    const double seconds = double(rendering.signal.size()) / render::kWavSampleRate;
    const Report report{written, rendering, options, sc, distance, compute / seconds};
    if (global.json)
      print_json(report);
    else if (!global.quiet)
      print_summary(report);
    if (!global.quiet && !global.json) print_notes(report);
    return 0;
  }

 private:
  struct Report {
    const render::WavSummary& wav;
    const render::Rendering& rendering;
    const render::RenderOptions& options;
    double convergence_db, distance_m_s2, compute_per_second;
  };

  render::RenderOptions render_options() const {
    render::RenderOptions o;
    if (live_ && reconstruction_ == "fgla" && reconstruct_option_->count() > 0)
      throw Error(Error::Kind::bad_input, "render: --live plays frame by frame: use --reconstruct online or noise, not fgla");
    o.reconstruction = render::parse_reconstruction(live_ && reconstruction_ == "fgla" ? "online" : reconstruction_);
    o.as_played = live_;
    o.fgla.seed = o.noise.seed = o.online.seed = seed_;
    // Review 6: --steady was taken with fgla and noise, where it does nothing.
    if (steady_ && o.reconstruction != render::Reconstruction::online)
      throw Error(Error::Kind::bad_input, "render: --steady: only the online reconstruction draws each frame's magnitudes; use it with "
                                          "--reconstruct online (or --live)");
    o.online.scatter = !steady_;
    o.online.look_ahead = std::size_t(look_ahead_);
    if (iterations_ >= 0) o.fgla.iterations = o.online.iterations = std::size_t(iterations_);
    if (o.reconstruction == render::Reconstruction::online && iterations_ == 0)
      throw Error(Error::Kind::bad_input, "render: the online reconstruction needs --iterations 1 or more (passes per frame)");
    return o;
  }

  std::string method(const render::RenderOptions& o) const {
    if (o.reconstruction == render::Reconstruction::fgla) return "fgla " + std::to_string(o.fgla.iterations) + " iterations";
    if (o.reconstruction == render::Reconstruction::noise)
      return "shaped noise, seed " + std::to_string(o.noise.seed) + (o.as_played ? " (live: delayed as played)" : "");
    return "online look-ahead " + std::to_string(o.online.look_ahead * 10) + " ms " + std::to_string(o.online.iterations) + " passes" +
           (o.online.scatter ? ", scattered (seed " + std::to_string(o.online.seed) + ")" : ", steady") +
           (o.as_played ? " (live: delayed as played)" : " (latency compensated)");
  }


  void print_summary(const Report& r) const {
    const double seconds = double(r.wav.samples) / render::kWavSampleRate;
    const std::string sc = std::isnan(r.convergence_db) ? std::string("SC n/a (under 0.1 s)") : text::format("SC %.1f dB", r.convergence_db);
    // Under a second, the start-up of the render outweighs the vibration: a rate per second would mislead.
    const std::string compute = seconds >= 1 ? text::format("%.3g s compute per s of vibration", r.compute_per_second)
                                             : text::format("%.3g s compute", r.compute_per_second * seconds);
    std::cout << text::format("wrote %s%s: %zu samples, %.3f s, peak %.4g m/s^2, full scale %.9g m/s^2 (24-bit PCM), %s, %s, %s\n",
                text::printable(output_).c_str(), csv_.empty() ? "" : (" and " + text::printable(csv_)).c_str(), r.wav.samples, seconds, r.wav.peak_m_s2,
                r.wav.full_scale_m_s2, method(r.options).c_str(), sc.c_str(), compute.c_str());
  }

  void print_notes(const Report& r) const {
    const std::size_t frames = r.rendering.targets.frames;
    if (r.rendering.saturated_frames > 0)
      std::cerr << "note: " << r.rendering.saturated_frames << " of " << frames
                << " frames had force or speed outside the training range; the model saturated them to the nearest trained value\n";
    if (texture_.reference.empty() && !texture_.image.empty())
      std::cerr << "note: no --reference: the image's own blur stands in for the no-contact frame\n";
    if (r.options.reconstruction != render::Reconstruction::fgla)
      std::cerr << text::format("note: slowest frame (predict + reconstruct) %.3f ms of the 10 ms budget; latency %zu ms\n",
                          r.rendering.slowest_frame_seconds * 1e3, r.rendering.latency_samples / 10);
  }

  void print_json(const Report& r) const {
    nlohmann::json out = {{"output", output_},
                          {"samples", r.wav.samples},
                          {"seconds", double(r.wav.samples) / render::kWavSampleRate},
                          {"sample_rate_hz", render::kWavSampleRate},
                          {"format", "WAV PCM 24-bit mono"},
                          {"peak_m_s2", r.wav.peak_m_s2},
                          {"full_scale_m_s2", r.wav.full_scale_m_s2},
                          {"reconstruction", render::reconstruction_name(r.options.reconstruction)},
                          {"live", r.options.as_played},
                          {"first_frame_sample", r.rendering.first_frame_sample},
                          {"frames", r.rendering.targets.frames},
                          {"saturated_frames", r.rendering.saturated_frames},
                          {"spectral_convergence_db", number_or_null(r.convergence_db)},
                          {"spectral_distance_m_s2", number_or_null(r.distance_m_s2)},
                          {"compute_seconds_per_second", r.compute_per_second}};
    if (!csv_.empty()) out["csv"] = csv_;
    if (r.options.reconstruction == render::Reconstruction::fgla) {
      out["iterations"] = r.options.fgla.iterations;
    } else {
      if (r.options.reconstruction == render::Reconstruction::online) {
        out["passes_per_frame"] = r.options.online.iterations;
        out["scatter"] = r.options.online.scatter;
        out["seed"] = r.options.online.seed;
      } else {
        out["seed"] = r.options.noise.seed;
      }
      out["latency_samples"] = r.rendering.latency_samples;
      out["slowest_frame_seconds"] = r.rendering.slowest_frame_seconds;
    }
    std::cout << out.dump(2) << "\n";
  }

  static nlohmann::json number_or_null(double x) { return std::isnan(x) ? nlohmann::json(nullptr) : nlohmann::json(x); }

  std::string model_path_, trajectory_path_, output_, csv_, reconstruction_ = "fgla";
  CLI::Option* reconstruct_option_ = nullptr;
  predict::TextureChoice texture_;
  int iterations_ = -1, look_ahead_ = 3;
  bool live_ = false, steady_ = false, force_ = false;
  double full_scale_ = 0;
  std::uint64_t seed_ = 0;
};

}  // namespace

std::unique_ptr<Command> make_render_command() { return std::make_unique<RenderCommand>(); }

}  // namespace haptex::apps
