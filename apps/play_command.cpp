// haptex play model.h5 (--image IMG [--reference REF] | --material ID) (--trajectory traj.csv | --actions -)
//             [--device NAME] [--record out.wav] [--reconstruct online|noise] [--look-ahead F] [--steady]
//             [--seed S] [--full-scale A] [--buffer-ms MS] [--force]
// The model as a live haptic loop on a sound card (docs/play.md). Ctrl-C or the end of the input stops
// it; --record keeps what was played and the actions it was played from.
#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <optional>

#include <nlohmann/json.hpp>

#include "apps/command.hpp"
#include "apps/input_file_option.hpp"
#include "apps/number_checks.hpp"
#include "apps/output_options.hpp"
#include "apps/stop_on_signal.hpp"
#include "apps/texture_options.hpp"
#include "core/durable_file.hpp"
#include "core/error.hpp"
#include "core/output_is_input.hpp"
#include "core/output_set.hpp"
#include "core/text/format.hpp"
#include "core/text/utf8.hpp"
#include "dataset/window.hpp"
#include "play/alsa_output.hpp"
#include "play/device_name.hpp"
#include "play/player.hpp"
#include "predict/model_file.hpp"
#include "render/wav_writer.hpp"

namespace haptex::apps {
namespace {

// The actions CSV beside a recording: out.wav -> out.csv.
std::string actions_path(const std::string& record) {
  std::filesystem::path p(record);
  return (p.extension() == ".wav" || p.extension() == ".WAV" ? p.replace_extension(".csv") : std::filesystem::path(record + ".csv")).string();
}

class PlayCommand : public Command {
 public:
  std::string name() const override { return "play"; }
  std::string summary() const override {
    return "Play the model live on a sound card: every 10 ms the newest force and speed become vibration";
  }

  void declare(CLI::App& app) override {
    app.add_option("model", model_path_, "Model file (haptex train)")->required()->check(input_file());
    add_texture_options(app, texture_);
    auto* trajectory = app.add_option("--trajectory", trajectory_path_, "Force/speed trajectory at 10 kHz, played at its own pace")
                           ->check(input_file());
    auto* actions = app.add_option("--actions", actions_, "- : a live stream on standard input, one 'force speed' or 't,force,speed' line per sample");
    trajectory->excludes(actions);
    app.add_option("--device", device_, "ALSA playback device (default, plughw:CARD,DEVICE, or one an ALSA configuration defines)")
        ->capture_default_str();
    app.add_option("--record", record_, "Keep what was played as a WAV (16-bit, the card's rate) and the actions as CSV beside it (NAME.csv)");
    add_force_option(app, force_);
    app.add_option("--reconstruct", reconstruction_, "Phase: online (RTISI-LA, 30 ms look-ahead) or noise (shaped white noise, no look-ahead)")
        ->capture_default_str()->check(CLI::IsMember({"online", "noise"}));
    app.add_option("--look-ahead", look_ahead_, "online: frames of look-ahead (latency 10 ms each)")->capture_default_str()->check(CLI::Range(0, 100));
    app.add_flag("--steady", steady_, "online: play the predicted spectra as they are, without drawing each frame around them");
    app.add_option("--seed", seed_, "online: seed of the frames' scatter; noise: of the noise")->check(seed_number())->capture_default_str();
    app.add_option("--full-scale", full_scale_, "m/s^2 at the card's full scale (louder samples clip and are counted)")
        ->capture_default_str()->check(positive_number())->check(CLI::Range(0.0, dataset::kLargestAccelerationMs2));
    app.add_option("--buffer-ms", buffer_ms_, "The device's buffer in 10 ms periods' worth (latency against underruns)")
        ->capture_default_str()->check(CLI::IsMember({20, 30, 40, 50, 60, 80, 100}));
  }

  bool ends_on_signals_itself() const override { return true; }  // StopOnSignal: the recording is kept

  int run(const GlobalOptions& global) override {
    require_texture(texture_, "play");
    if (trajectory_path_.empty() && actions_.empty())
      throw Error(Error::Kind::bad_input, "play: give --trajectory FILE, or --actions - for a live stream on standard input");
    if (!actions_.empty() && actions_ != "-")
      throw input_error(actions_, "", "--actions reads standard input only", "Give --actions -, or play a file with --trajectory");
    if (steady_ && reconstruction_ != "online")
      throw Error(Error::Kind::bad_input, "play: --steady: only the online reconstruction draws each frame's magnitudes");
    check_outputs();
    const predict::Model model = predict::read_model(model_path_);
    const predict::TextureCode code = predict::choose_texture(predict::Predictor(model), model_path_, texture_);
    std::optional<predict::Trajectory> trajectory;
    if (!trajectory_path_.empty()) trajectory = predict::read_trajectory(trajectory_path_);

    // The recording's names are taken before anything plays, so a second run with the same --record
    // is refused at once, not after its session (review 12, F2).
    std::optional<Recording> recording;
    if (!record_.empty()) recording.emplace(record_, force_);
    play::AlsaOutput output(play::checked_device_name(device_), unsigned(buffer_ms_ / 10));
    play::Player player(model, code, options(), output);
    if (!global.quiet && !global.json) print_start(output, player.latency());
    play::PlayReport report;
    try {
      StopOnSignal stop_on_signal;
      if (trajectory) {
        report = player.play(*trajectory, StopOnSignal::stop_requested());
      } else {
        play::ActionStream stream(STDIN_FILENO, "standard input");
        report = player.play(stream, StopOnSignal::stop_requested());
      }
    } catch (...) {
      // A bad line in the stream, a device unplugged: what was played until then is kept.
      if (recording && player.played_trajectory().force.size() > 0) write_record(*recording, player, output.rate(), global);
      throw;
    }
    if (recording) write_record(*recording, player, output.rate(), global);
    if (global.json)
      print_json(output, player.latency(), report);
    else if (!global.quiet)
      print_end(report, output);
    return 0;
  }

 private:
  play::PlayOptions options() const {
    play::PlayOptions o;
    o.reconstruction = render::parse_reconstruction(reconstruction_);
    o.online.look_ahead = std::size_t(look_ahead_);
    o.online.scatter = !steady_;
    o.online.seed = o.noise.seed = seed_;
    o.full_scale_m_s2 = full_scale_;
    o.keep_samples = !record_.empty();
    return o;
  }

  void check_outputs() const {
    if (record_.empty()) return;
    const std::vector<std::string> inputs{model_path_, trajectory_path_, texture_.image, texture_.reference,
                                          actions_ == "-" ? kStandardInput : ""};
    refuse_output_among_inputs(record_, inputs);
    refuse_output_among_inputs(actions_path(record_), inputs);
    render::check_wav_output(record_, force_);
    predict::check_trajectory_csv_output(actions_path(record_), force_);
  }

  // --record's two files under their temporary names, both appearing together or neither
  // (core/output_set.hpp): a full disk never leaves a WAV without its actions.
  struct Recording {
    PartialFile wav, csv;
    Recording(const std::string& record, bool force)
        : wav(record, force, [](const std::string& p) { render::check_wav_output(p, true); }),
          csv(actions_path(record), force, [](const std::string& p) { predict::check_trajectory_csv_output(p, true); }) {}
  };

  void write_record(Recording& recording, const play::Player& player, unsigned rate, const GlobalOptions& global) const {
    render::WavOptions wav;
    wav.full_scale_m_s2 = full_scale_;
    wav.overwrite = force_;
    wav.title = texture_.material.empty() ? texture_.image : texture_.material;
    wav.source = global.command_line + ", as played";
    render::write_played_wav(recording.wav, player.played_samples(), int(rate), wav);
    write_text(recording.csv, predict::trajectory_csv_text(player.played_trajectory()));
    commit_together({&recording.wav, &recording.csv});
  }

  void print_start(const play::AlsaOutput& output, const play::Latency& l) const {
    std::cerr << text::format("playing on %s\nlatency %.0f ms: frame %.0f + look-ahead %.0f + resampler %.1f + buffer %.0f ms\n",
                              text::printable(output.description()).c_str(), l.total_ms(), l.frame_ms, l.look_ahead_ms,
                              l.resampler_ms, l.buffer_ms);
  }

  void print_end(const play::PlayReport& r, const play::AlsaOutput& output) const {
    const unsigned rate = output.rate();
    if (!output.clocked()) std::cerr << "note: the device keeps no time (an ALSA null or file plugin): haptex's clock paced it\n";
    std::cout << text::format("played %.2f s (%zu frames; %s): %llu underruns, %llu late periods, %llu clipped samples, "
                              "slowest frame %.2f ms of 10",
                              double(r.samples_played) / rate, r.ticks,
                              r.ended_by == "interrupted" ? "stopped by a signal" : ("to the " + r.ended_by).c_str(), (unsigned long long)r.underruns,
                              (unsigned long long)r.late_periods, (unsigned long long)r.clipped_samples, r.slowest_tick_ms)
              << (record_.empty() ? "" : "; recorded " + text::printable(record_) + " and " + text::printable(actions_path(record_)))
              << "\n";
    if (r.saturated_ticks > 0)
      std::cerr << "note: " << r.saturated_ticks << " of " << r.ticks
                << " frames had force or speed outside the training range; the model saturated them\n";
  }

  void print_json(const play::AlsaOutput& output, const play::Latency& l, const play::PlayReport& r) const {
    nlohmann::json out = {{"device", output.description()},
                          {"clock", output.clocked() ? "device" : "haptex (the device keeps no time)"},
                          {"rate_hz", output.rate()},
                          {"period_samples", output.period_samples()},
                          {"buffer_samples", output.buffer_samples()},
                          {"latency_ms", {{"total", l.total_ms()}, {"frame", l.frame_ms}, {"look_ahead", l.look_ahead_ms},
                                          {"resampler", l.resampler_ms}, {"buffer", l.buffer_ms}}},
                          {"reconstruction", reconstruction_},
                          {"seed", seed_},
                          {"full_scale_m_s2", full_scale_},
                          {"frames", r.ticks},
                          {"saturated_frames", r.saturated_ticks},
                          {"samples_played", r.samples_played},
                          {"first_sound_sample", r.first_sound_sample},
                          {"clipped_samples", r.clipped_samples},
                          {"underruns", r.underruns},
                          {"late_periods", r.late_periods},
                          {"slowest_frame_ms", r.slowest_tick_ms},
                          {"line_to_device_ms", {{"median", r.line_to_device_median_ms}, {"p99", r.line_to_device_p99_ms}}},
                          {"cpu_share", cpu_share()},
                          {"ended_by", r.ended_by}};
    if (!record_.empty()) out["record"] = {{"wav", record_}, {"actions", actions_path(record_)}};
    std::cout << out.dump(2) << "\n";
  }

  // The process's CPU time over its wall time since it started: the share of one core it took.
  static double cpu_share() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    const double cpu = double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) + 1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
    return wall > 0 ? cpu / wall : 0;
  }
  static inline const std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();

  std::string model_path_, trajectory_path_, actions_, device_ = "default", record_, reconstruction_ = "online";
  predict::TextureChoice texture_;
  int look_ahead_ = 3, buffer_ms_ = 30;
  bool steady_ = false, force_ = false;
  double full_scale_ = 50;
  std::uint64_t seed_ = 0;
};

}  // namespace

std::unique_ptr<Command> make_play_command() { return std::make_unique<PlayCommand>(); }

}  // namespace haptex::apps
