#include "render/vibration_render.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <memory>

#include "core/durable_file.hpp"
#include "core/error.hpp"
#include "core/signal/spectrum.hpp"
#include "dataset/window.hpp"
#include "render/spectral_convergence.hpp"

namespace haptex::render {
namespace {

constexpr std::size_t kHop = kReconstructionHop;

void check_trajectory(const predict::Trajectory& t) {
  if (t.force.size() != t.speed.size())
    throw Error(Error::Kind::bad_input, "render: the trajectory has " + std::to_string(t.force.size()) + " force and " +
                                            std::to_string(t.speed.size()) + " speed samples; they must pair up");
  if (t.force.size() < kMinTrajectorySamples)
    throw Error(Error::Kind::bad_input, "render: the trajectory has " + std::to_string(t.force.size()) +
                                            " samples; a rendering needs at least " + min_trajectory_text());
}

// Copies samples that start at `position` of the output into `signal`, dropping those past its end.
void place(std::span<const double> samples, std::size_t position, std::vector<double>& signal) {
  for (std::size_t i = 0; i < samples.size() && position + i < signal.size(); ++i) signal[position + i] = samples[i];
}

void render_offline(const predict::Model& model, const predict::TextureCode& code, const predict::Trajectory& trajectory,
                    const RenderOptions& options, Rendering& out) {
  predict::Predictor predictor(model);
  float action[dataset::kActionValues];
  for (std::size_t m = 0; m < out.targets.frames; ++m) {
    predict::action_at(trajectory, frame_action_sample(m, trajectory.force.size()), action);
    const auto row = std::span(out.spectra).subspan(m * dataset::kTargetBins, dataset::kTargetBins);
    if (predictor.predict(code, action, row)) ++out.saturated_frames;
    target_magnitude_frame(std::span<const float>(row), out.targets.row(m));
  }
  const std::vector<double> x = griffin_lim(out.targets, out.signal.size() - out.first_frame_sample, options.fgla);
  place(x, out.first_frame_sample, out.signal);
}

void render_online(const predict::Model& model, const predict::TextureCode& code, const predict::Trajectory& trajectory,
                   const RenderOptions& options, Rendering& out) {
  VibrationLoop loop = options.reconstruction == Reconstruction::noise ? VibrationLoop(model, code, options.noise)
                                                                       : VibrationLoop(model, code, options.online);
  out.latency_samples = loop.latency_samples();
  if (options.as_played) out.first_frame_sample += dataset::kActionEnd + out.latency_samples + 1;
  float action[dataset::kActionValues];
  std::size_t position = out.first_frame_sample;  // where the next returned sample belongs
  for (std::size_t m = 0; m < out.targets.frames; ++m) {
    predict::action_at(trajectory, frame_action_sample(m, trajectory.force.size()), action);
    const auto start = std::chrono::steady_clock::now();
    const std::span<const double> samples = loop.tick(action);
    out.slowest_frame_seconds =
        std::max(out.slowest_frame_seconds, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    if (loop.saturated()) ++out.saturated_frames;
    std::copy(loop.magnitudes().begin(), loop.magnitudes().end(), out.targets.row(m).begin());
    std::copy(loop.spectrum().begin(), loop.spectrum().end(), out.spectra.begin() + std::ptrdiff_t(m * dataset::kTargetBins));
    place(samples, position, out.signal);
    position += samples.size();
  }
  place(loop.flush(), position, out.signal);
}

}  // namespace

std::string min_trajectory_text() {
  const auto ms = std::lround(double(kMinTrajectorySamples) * 1000.0 / dataset::kSampleRateHz);
  return std::to_string(kMinTrajectorySamples) + " samples (" + std::to_string(ms) + " ms)";
}

std::size_t render_frames(std::size_t n) { return n < kMinTrajectorySamples ? 0 : (n - 1) / kHop + 1; }

std::size_t frame_action_sample(std::size_t m, std::size_t n) { return std::min(m * kHop + dataset::kActionEnd, n - 1); }

Rendering render_vibration(const predict::Model& model, const predict::TextureCode& code, const predict::Trajectory& trajectory,
                           const RenderOptions& options) {
  check_trajectory(trajectory);
  Rendering out;
  out.signal.assign(trajectory.force.size(), 0.0);
  out.targets.frames = render_frames(trajectory.force.size());
  out.targets.bins = kReconstructionBins;
  out.targets.values.assign(out.targets.frames * kReconstructionBins, 0.0);
  out.spectra.assign(out.targets.frames * dataset::kTargetBins, 0.0f);
  if (options.reconstruction == Reconstruction::fgla)
    render_offline(model, code, trajectory, options, out);
  else
    render_online(model, code, trajectory, options, out);
  return out;
}

std::size_t complete_frames(const Rendering& rendering) {
  const std::size_t n = rendering.signal.size(), first = rendering.first_frame_sample;
  if (n < first + dataset::kWindowSamples) return 0;
  return std::min(rendering.targets.frames, (n - first - dataset::kWindowSamples) / kHop + 1);
}

double rendered_convergence_db(const Rendering& rendering) {
  const std::size_t frames = complete_frames(rendering);
  if (frames == 0) return std::numeric_limits<double>::quiet_NaN();
  MagnitudeFrames s{frames, kReconstructionBins, {}};
  const auto first = rendering.targets.values.begin();
  s.values.assign(first, first + std::ptrdiff_t(frames * kReconstructionBins));
  return spectral_convergence_db(std::span(rendering.signal).subspan(rendering.first_frame_sample), s);
}

std::string vibration_csv_text(const predict::Trajectory& trajectory, std::span<const double> signal) {
  if (signal.size() != trajectory.force.size() || signal.size() != trajectory.speed.size())
    throw failure("internal: the signal has " + std::to_string(signal.size()) + " samples, the trajectory " +
                  std::to_string(trajectory.force.size()) + "; they must match");
  std::string text = std::string(kVibrationCsvHeader) + "\n";
  char row[128];
  for (std::size_t i = 0; i < signal.size(); ++i) {
    const int n = std::snprintf(row, sizeof row, "%.4f,%.9g,%.9g,%.9g\n", double(i) * 1e-4, double(trajectory.force[i]),
                                double(trajectory.speed[i]), signal[i]);
    text.append(row, std::size_t(n));
  }
  return text;
}

void write_vibration_csv(const std::string& path, const predict::Trajectory& trajectory, std::span<const double> signal,
                         bool overwrite) {
  check_vibration_csv_output(path, overwrite);
  write_file_durably(path, vibration_csv_text(trajectory, signal), overwrite,
                     [](const std::string& p) { check_vibration_csv_output(p, true); });
}

bool is_vibration_csv(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string first(kVibrationCsvHeader.size() + 1, '\0');
  return in.read(first.data(), std::streamsize(first.size())) && first == std::string(kVibrationCsvHeader) + "\n";
}

void check_vibration_csv_output(const std::string& path, bool overwrite) {
  check_replaceable_output(path, overwrite, "a CSV haptex render wrote (its first line " + std::string(kVibrationCsvHeader) + ")",
                           is_vibration_csv);
}

double rendered_distance(const Rendering& rendering) {
  const std::size_t frames = complete_frames(rendering);
  if (frames == 0) return std::numeric_limits<double>::quiet_NaN();
  std::vector<double> amplitudes(dataset::kTargetBins), predicted(dataset::kTargetBins);
  double sum = 0;
  for (std::size_t m = 0; m < frames; ++m) {
    const auto window = std::span(rendering.signal).subspan(rendering.first_frame_sample + m * kHop, dataset::kWindowSamples);
    signal::amplitude_spectrum(window, amplitudes);
    const auto row = rendering.spectra.begin() + std::ptrdiff_t(m * dataset::kTargetBins);
    std::copy(row, row + dataset::kTargetBins, predicted.begin());
    sum += signal::spectrum_distance(amplitudes, predicted);
  }
  return sum / double(frames);
}

VibrationLoop::VibrationLoop(const predict::Model& model, const predict::TextureCode& code,
                             const OnlineReconstructionOptions& options)
    : predictor_(model),
      code_(code),
      reconstruction_(options),
      spectrum_(dataset::kTargetBins),
      magnitudes_(kReconstructionBins) {}

VibrationLoop::VibrationLoop(const predict::Model& model, const predict::TextureCode& code, const ShapedNoiseOptions& options)
    : predictor_(model),
      code_(code),
      shaped_(options),
      noise_(true),
      spectrum_(dataset::kTargetBins),
      magnitudes_(kReconstructionBins) {}

std::span<const double> VibrationLoop::tick(std::span<const float> action) {
  saturated_ = predictor_.predict(code_, action, spectrum_);
  target_magnitude_frame(std::span<const float>(spectrum_), magnitudes_);
  return noise_ ? shaped_.push(magnitudes_) : reconstruction_.push(magnitudes_);
}

}  // namespace haptex::render
