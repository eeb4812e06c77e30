#pragma once
// `haptex play`: the model as a live haptic loop (docs/play.md). Every 10 ms the player takes the
// newest action, predicts its spectrum, gives it a phase (render's VibrationLoop: RTISI-LA or shaped
// noise), resamples the 100 samples to the card's rate (core/signal/resample.hpp, StreamResampler)
// and hands one period to the AudioOutput, which paces it.
//
// Frames and the trajectory. Tick m takes the action ending at sample m * 100 + 500 of a 10 kHz
// trajectory, as `haptex render --live` does for frame m (render/vibration_render.hpp), and after
// the last sample the loop plays out the frames whose middle lies past it with the last action held,
// as render does. So a recorded session (played_trajectory) rendered by `render --live` with the
// same method and seed gives, resampled the same way, the samples that were played.
//   - A trajectory file is played at its own pace: all its samples are known.
//   - A live stream (ActionStream): the first tick comes 50 ms after the first line (an action spans
//     45 ms), tick m at that moment plus m x 10 ms; a line sets the trajectory from the sample of its
//     arrival on (10 kHz, the value held until the next line).
#include <atomic>
#include <optional>
#include <cstdint>
#include <string>
#include <vector>

#include "core/signal/resample.hpp"
#include "play/action_stream.hpp"
#include "play/audio_output.hpp"
#include "predict/predictor.hpp"
#include "predict/trajectory.hpp"
#include "render/vibration_render.hpp"

namespace haptex::play {

struct PlayOptions {
  render::Reconstruction reconstruction = render::Reconstruction::online;  // online or noise: live methods
  render::OnlineReconstructionOptions online{.scatter = true};
  render::ShapedNoiseOptions noise;
  double full_scale_m_s2 = 0;  // m/s^2 at 16-bit full scale (render's --full-scale); louder samples clip, counted
  bool keep_samples = false;   // keep what was played (played_samples) for a recording
};

// Milliseconds from an action to the sound it makes: waiting for the next tick (one frame), the
// reconstruction's look-ahead, the resampler's filter and the device's buffer.
struct Latency {
  double frame_ms = 10, look_ahead_ms = 0, resampler_ms = 0, buffer_ms = 0;
  double total_ms() const { return frame_ms + look_ahead_ms + resampler_ms + buffer_ms; }
};

struct PlayReport {
  std::size_t ticks = 0, saturated_ticks = 0;  // saturated: the action lay outside the training range
  std::size_t samples_played = 0;              // at the device's rate, the start's silence included
  std::size_t first_sound_sample = 0;          // played sample where the rendering's (resampled) sample 0 lies
  std::uint64_t clipped_samples = 0, underruns = 0, late_periods = 0;
  double slowest_tick_ms = 0;                  // predict + phase + resample of one frame
  // A live stream: from a line's arrival to the period holding the first samples of the frame it was
  // the newest action of, handed to the device (the device's buffer comes after); median and 99th
  // percentile over the frames that had a new line.
  double line_to_device_median_ms = 0, line_to_device_p99_ms = 0;
  std::string ended_by;                        // "end of the trajectory", "end of the input", "interrupted"
};

class Player {
 public:
  // Keeps references to the model and the output, which must outlive the player.
  Player(const predict::Model& model, const predict::TextureCode& code, const PlayOptions& options, AudioOutput& output);

  Latency latency() const;
  PlayReport play(const predict::Trajectory& trajectory, const std::atomic<bool>& stop);
  PlayReport play(ActionStream& stream, const std::atomic<bool>& stop);

  // What was played from (10 kHz) and what was handed to the device (16-bit, its rate; kept only
  // with PlayOptions::keep_samples).
  const predict::Trajectory& played_trajectory() const { return trajectory_; }
  const std::vector<std::int16_t>& played_samples() const { return played_; }

 private:
  void tick(std::size_t m);
  std::int16_t pcm(double m_s2);  // counts a clipped sample
  void keep(std::span<const std::int16_t> period);  // counts it, and keeps it when recording
  void hand_over(bool sounds);  // resampled_ holds the tick's samples at the output's rate
  void finish(bool interrupted);
  render::VibrationLoop loop_;
  PlayOptions options_;
  AudioOutput& output_;
  signal::StreamResampler resampler_;
  predict::Trajectory trajectory_;
  std::vector<double> resampled_;
  std::vector<std::int16_t> pending_, played_;
  bool sounding_ = false;  // the loop has returned samples
  std::vector<std::optional<Clock::time_point>> newest_line_;  // per tick, a live stream's newest line's arrival
  std::vector<double> line_to_device_ms_;
  PlayReport report_;
};

}  // namespace haptex::play
