#include "play/player.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

#include "core/error.hpp"
#include "dataset/window.hpp"

namespace haptex::play {
namespace {

constexpr std::size_t kHop = render::kReconstructionHop;              // 100 samples, 10 ms
constexpr auto kSampleTime = std::chrono::microseconds(100);          // 10 kHz
const double kRateHz = dataset::kSampleRateHz;

render::VibrationLoop make_loop(const predict::Model& model, const predict::TextureCode& code, const PlayOptions& o) {
  if (o.reconstruction == render::Reconstruction::fgla)
    throw Error(Error::Kind::bad_input, "play: fast Griffin-Lim needs the whole signal; play with online or noise");
  if (!(o.full_scale_m_s2 > 0)) throw failure("internal: play needs a full scale above 0");
  return o.reconstruction == render::Reconstruction::noise ? render::VibrationLoop(model, code, o.noise)
                                                            : render::VibrationLoop(model, code, o.online);
}

}  // namespace

Player::Player(const predict::Model& model, const predict::TextureCode& code, const PlayOptions& options, AudioOutput& output)
    : loop_(make_loop(model, code, options)),
      options_(options),
      output_(output),
      resampler_(int(output.rate()), int(kRateHz)) {}

Latency Player::latency() const {
  Latency l;
  l.look_ahead_ms = 1000.0 * double(loop_.latency_samples()) / kRateHz;
  l.resampler_ms = 1000.0 * double(resampler_.delay_inputs()) / kRateHz;
  l.buffer_ms = 1000.0 * double(output_.buffer_samples()) / output_.rate();
  return l;
}

// Frame m from the action ending at its middle (or the trajectory's last sample), as render does.
void Player::tick(std::size_t m) {
  float action[dataset::kActionValues];
  predict::action_at(trajectory_, render::frame_action_sample(m, trajectory_.force.size()), action);
  const auto start = std::chrono::steady_clock::now();
  const std::span<const double> samples = loop_.tick(action);
  resampler_.push(samples, resampled_);
  report_.slowest_tick_ms =
      std::max(report_.slowest_tick_ms, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  if (loop_.saturated()) ++report_.saturated_ticks;
  ++report_.ticks;
  hand_over(!samples.empty());
}

std::int16_t Player::pcm(double a) {
  double s = a / options_.full_scale_m_s2;
  if (std::abs(s) > 1) {
    ++report_.clipped_samples;
    s = std::clamp(s, -1.0, 1.0);
  }
  return std::int16_t(std::lrint(s * 32767));
}

// Scales the resampled samples to 16 bits and hands the complete periods to the output: a period of
// silence for each tick before the loop sounds, and silence before its first samples to fill their
// period (the filter returns its first outputs a millisecond late).
void Player::hand_over(bool sounds) {
  const std::size_t period = output_.period_samples();
  for (const double a : resampled_) pending_.push_back(pcm(a));
  if (!sounding_ && sounds) {
    sounding_ = true;
    const std::size_t lead = (period - pending_.size() % period) % period;
    pending_.insert(pending_.begin(), lead, 0);
    report_.first_sound_sample = report_.samples_played + lead;
  }
  if (!sounding_) pending_.assign(period, 0);
  const bool handed = pending_.size() >= period;
  while (pending_.size() >= period) {
    output_.play(std::span(pending_).first(period));
    keep(std::span(pending_).first(period));
    pending_.erase(pending_.begin(), pending_.begin() + std::ptrdiff_t(period));
  }
  // The frame whose first samples just went out was predicted look-ahead ticks ago.
  const std::size_t lag = loop_.latency_samples() / kHop;
  if (handed && report_.ticks > lag && report_.ticks - 1 - lag < newest_line_.size())
    if (const auto& line = newest_line_[report_.ticks - 1 - lag])
      line_to_device_ms_.push_back(std::chrono::duration<double, std::milli>(Clock::now() - *line).count());
}

void Player::keep(std::span<const std::int16_t> period) {
  report_.samples_played += period.size();
  if (options_.keep_samples) played_.insert(played_.end(), period.begin(), period.end());
}

void Player::finish(bool interrupted) {
  if (report_.ticks == 0) return;  // stopped before the device started
  const std::span<const double> rest = loop_.flush();
  resampler_.push(rest, resampled_);
  hand_over(!rest.empty());
  resampler_.flush(resampled_);
  for (const double a : resampled_) pending_.push_back(pcm(a));
  if (!pending_.empty()) {
    pending_.resize(output_.period_samples(), 0);  // the last period ends in silence
    output_.play(pending_);
    keep(pending_);
    pending_.clear();
  }
  if (!interrupted) output_.drain();
  report_.underruns = output_.underruns();
  report_.late_periods = output_.late_periods();
  if (!line_to_device_ms_.empty()) {
    std::sort(line_to_device_ms_.begin(), line_to_device_ms_.end());
    const auto at = [&](double q) { return line_to_device_ms_[std::size_t(q * double(line_to_device_ms_.size() - 1))]; };
    report_.line_to_device_median_ms = at(0.5);
    report_.line_to_device_p99_ms = at(0.99);
  }
}

PlayReport Player::play(const predict::Trajectory& trajectory, const std::atomic<bool>& stop) {
  trajectory_ = trajectory;
  const std::size_t frames = render::render_frames(trajectory_.force.size());
  output_.start();
  for (std::size_t m = 0; m < frames && !stop; ++m) tick(m);
  report_.ended_by = stop ? "interrupted" : "end of the trajectory";
  finish(stop);
  return report_;
}

PlayReport Player::play(ActionStream& stream, const std::atomic<bool>& stop) {
  if (!stream.wait_for_first(stop)) {
    if (const std::exception_ptr bad = stream.error()) std::rethrow_exception(bad);
    if (!stop) throw input_error(stream.source(), "", "ended before its first action", "Give one 'force speed' line per sample (N, mm/s)");
    report_.ended_by = "interrupted";
    return report_;
  }
  std::deque<ActionLine> lines, more;
  stream.take(Clock::now(), lines);
  const Clock::time_point first = lines.front().arrived;
  const auto sample_of = [&](Clock::time_point t) { return std::size_t(std::max<std::int64_t>(0, (t - first) / kSampleTime)); };
  // Sets the trajectory from each line's sample on, then holds the newest value up to `last`. The
  // samples earlier ticks played are kept as they were; lines that arrived within one sample (a burst
  // read at once) share it, the newest winning (review 11, F1: each took a sample of its own, so a
  // burst of 30 000 lines delayed every later action by 3 s).
  const auto extend = [&](std::size_t last) {
    const std::size_t played = trajectory_.force.size();
    for (const ActionLine& line : lines) {
      const std::size_t at = std::max(sample_of(line.arrived), played);
      if (at < trajectory_.force.size()) {
        trajectory_.force.back() = line.force;
        trajectory_.speed.back() = line.speed;
        continue;
      }
      trajectory_.force.resize(at, trajectory_.force.empty() ? line.force : trajectory_.force.back());
      trajectory_.speed.resize(at, trajectory_.speed.empty() ? line.speed : trajectory_.speed.back());
      trajectory_.force.push_back(line.force);
      trajectory_.speed.push_back(line.speed);
    }
    lines.clear();
    trajectory_.force.resize(std::max(trajectory_.force.size(), last + 1), trajectory_.force.back());
    trajectory_.speed.resize(std::max(trajectory_.speed.size(), last + 1), trajectory_.speed.back());
  };
  bool more_to_come = true;
  std::size_t m = 0;
  for (; more_to_come && !stop; ++m) {
    const std::size_t last = m * kHop + dataset::kActionEnd;
    const Clock::time_point due = first + kSampleTime * std::int64_t(last);
    std::this_thread::sleep_until(due);
    if (m == 0) output_.start();
    more_to_come = stream.take(due, more);
    lines.insert(lines.end(), more.begin(), more.end());
    newest_line_.push_back(lines.empty() ? std::nullopt : std::optional(lines.back().arrived));
    extend(last);
    tick(m);
  }
  // The input ended: the frames whose middle lies past its last sample, the action held, as render plays them.
  for (const std::size_t frames = render::render_frames(trajectory_.force.size()); m < frames && !stop; ++m) tick(m);
  report_.ended_by = stop ? "interrupted" : "end of the input";
  finish(stop);
  if (const std::exception_ptr bad = stream.error()) std::rethrow_exception(bad);  // after playing the lines before it
  return report_;
}

}  // namespace haptex::play
