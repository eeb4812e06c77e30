#pragma once
// Rendering a force/speed trajectory into vibration (issue 7): what `haptex render` writes to a WAV
// for a voice-coil actuator, and what a 1 kHz haptic loop plays.
//
// Along a trajectory of N samples at 10 kHz, frame m covers the 1000 samples from s_m = 100 m, for
// s_m <= N - 1; the model predicts its 100-bin amplitude spectrum from the action ending at its middle,
// s_m + 500 (the model's sample, dataset/window.hpp; held at the trajectory's last sample for the
// frames whose middle lies past it). Each frame is converted to Hann-STFT magnitudes
// (target_magnitude_frame) and given a phase by
//   - fgla: the offline fast Griffin-Lim over all frames at once (render/griffin_lim.hpp), or
//   - online: RTISI-LA, one frame pushed per 100 samples as a live loop would (VibrationLoop below,
//     render/online_reconstruction.hpp): nothing is allocated per frame;
//   - noise: no phase at all: white noise shaped to each frame (render/shaped_noise.hpp), which
//     varies from window to window as a surface does; offline and live alike, without look-ahead.
//
// Timing. The returned signal has one sample per trajectory sample (m/s^2). Frame m starts at
// sample first_frame_sample + 100 m: by default at s_m itself, where the model places the spectrum
// it predicts, so the first ~900 samples fade in (fewer frames overlap there;
// render/target_magnitudes.hpp, synthesis_gain). The online method's look-ahead (30 ms by
// default) is compensated the same way: its samples are placed where they belong, not where they
// came out, so fgla and online renderings line up with each other and with the trajectory. With
// RenderOptions::as_played the online samples are instead placed where the live loop plays them:
// the tick at s_m + 500 (when the action ending there is known) plays its 100 samples from the next
// sample on, so everything comes 500 + latency_samples + 1 samples later.
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "predict/predictor.hpp"
#include "predict/trajectory.hpp"
#include "render/griffin_lim.hpp"
#include "render/online_reconstruction.hpp"
#include "render/reconstruction.hpp"
#include "render/shaped_noise.hpp"
#include "render/target_magnitudes.hpp"

namespace haptex::render {

// The shortest trajectory a rendering takes: 1 ms (predict/trajectory.hpp). (The action needs no
// history: before a trajectory's first sample, that sample stands in, dataset::action_ending_at.)
using predict::kMinTrajectorySamples;
// "10 samples (1 ms)", for the messages that refuse a shorter trajectory.
std::string min_trajectory_text();
// The trajectory sample frame m's action ends at: its middle, or the trajectory's last sample.
std::size_t frame_action_sample(std::size_t m, std::size_t n);

struct RenderOptions {
  Reconstruction reconstruction = Reconstruction::fgla;
  GriffinLimOptions fgla;              // 100 iterations, momentum 0.99, seeded random initial phase
  // look-ahead 3 frames (30 ms), 4 passes per frame, each frame drawn around the prediction (scatter)
  OnlineReconstructionOptions online{.scatter = true};
  ShapedNoiseOptions noise;            // noise: the noise's seed
  bool as_played = false;              // online and noise: place samples where a live loop plays them
};

struct Rendering {
  std::vector<double> signal;       // m/s^2, one sample per trajectory sample
  std::vector<float> spectra;       // frames x 100 predicted amplitudes (m/s^2, bins 10..1000 Hz), row-major
  MagnitudeFrames targets;          // the predicted frames (x 501 Hann magnitudes), frame m from
  std::size_t first_frame_sample = 0;  // <- this sample + 100 m of `signal`
  std::size_t latency_samples = 0;  // online: look-ahead x 100 (compensated unless as_played); fgla, noise: 0
  std::size_t saturated_frames = 0; // frames whose action lay outside the training range (saturated)
  double slowest_frame_seconds = 0; // online: the slowest predict + convert + push of one frame
};

// Number of frames along a trajectory of n samples: one per 100 samples from sample 0 on (none
// when n < 10).
std::size_t render_frames(std::size_t n);

// Throws haptex::Error (bad_input) when the trajectory has fewer than kMinTrajectorySamples or its force and
// speed columns differ in length, and for RenderOptions the reconstructions refuse.
Rendering render_vibration(const predict::Model& model, const predict::TextureCode& code,
                           const predict::Trajectory& trajectory, const RenderOptions& options = {});

// Spectral convergence (render/spectral_convergence.hpp) of the rendered signal against the
// predicted frames that lie wholly inside it (complete_frames); NaN when none does (a trajectory
// shorter than first_frame_sample + 1000 samples).
std::size_t complete_frames(const Rendering& rendering);
double rendered_convergence_db(const Rendering& rendering);
// The evaluation's measure (signal::spectrum_distance) on the same frames: the mean Euclidean
// distance (m/s^2) between the 100-bin amplitude spectrum (rectangular window) of the rendered
// samples each complete frame covers and the spectrum predicted for it; NaN when no frame is
// complete. Read it against the spectra's own norm (on the synthetic test problem: FGLA 28 % of
// it, online 39 %, the random initial phase 74 %).
double rendered_distance(const Rendering& rendering);

// The rendering as CSV, one row per sample, under the header kVibrationCsvHeader (the force and
// speed columns make it a trajectory that haptex predict and render read back). Written under a
// temporary name, synced and renamed; throws haptex::Error (bad_input) naming the file when it exists
// and overwrite is false or it is not such a CSV, (failed) when the write fails.
inline constexpr std::string_view kVibrationCsvHeader = "time_s,force_n,speed_mm_s,accel_m_s2";
void write_vibration_csv(const std::string& path, const predict::Trajectory& trajectory, std::span<const double> signal,
                         bool overwrite);
// The CSV's text (for a caller committing it with other outputs: core/durable_file.hpp, write_text).
std::string vibration_csv_text(const predict::Trajectory& trajectory, std::span<const double> signal);
// Whether path is a CSV write_vibration_csv wrote (its first line is the header): what --force replaces.
bool is_vibration_csv(const std::string& path);
// check_replaceable_output for the CSV.
void check_vibration_csv_output(const std::string& path, bool overwrite);

// The live loop, one tick per 100 samples (10 ms): predict the spectrum for the action just
// measured, convert it, push it through the online reconstruction (or the shaped noise, with
// `noise`) and return the samples to play next. Everything is sized at construction; tick()
// allocates nothing. Keeps a reference to the model, which must outlive the loop.
class VibrationLoop {
 public:
  VibrationLoop(const predict::Model& model, const predict::TextureCode& code, const OnlineReconstructionOptions& options = {});
  // Shaped noise instead of RTISI-LA: no latency.
  VibrationLoop(const predict::Model& model, const predict::TextureCode& code, const ShapedNoiseOptions& options);

  std::size_t latency_samples() const { return noise_ ? 0 : reconstruction_.latency_samples(); }

  // action: dataset::kActionValues values (10 force in N, then 10 speed in mm/s, 5 ms apart, the newest
  // last: dataset::action_ending_at over the force and speed the loop has measured).
  // Returns the next 100 samples (m/s^2) once look_ahead frames are queued; before that, nothing.
  // The span stays valid until the next call.
  std::span<const double> tick(std::span<const float> action);
  // The last tick's action lay outside the training range and was saturated.
  bool saturated() const { return saturated_; }
  // The last tick's frame: 100 amplitudes (m/s^2) and 501 Hann magnitudes.
  std::span<const float> spectrum() const { return spectrum_; }
  std::span<const double> magnitudes() const { return magnitudes_; }
  // Ends the stream: the samples still held (OnlineReconstruction::flush, ShapedNoise::flush).
  std::span<const double> flush() { return noise_ ? shaped_.flush() : reconstruction_.flush(); }

 private:
  predict::Predictor predictor_;
  predict::TextureCode code_;
  OnlineReconstruction reconstruction_;
  ShapedNoise shaped_;
  bool noise_ = false;
  std::vector<float> spectrum_;
  std::vector<double> magnitudes_;
  bool saturated_ = false;
};

}  // namespace haptex::render
