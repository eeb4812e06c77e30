// signal.*: NaN/Inf, sample rate, duration, clipping, physical force and speed, acceleration band.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "qa/band_power.hpp"
#include "qa/checkers.hpp"
#include "qa/thresholds.hpp"

namespace haptex::qa {
namespace {

// Samples sitting in flat tops: runs of >= kClipRunSamples identical values at the maximum or minimum.
std::size_t flat_top_samples(const std::vector<double>& x) {
  if (x.empty()) return 0;
  const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
  const double extremes[2] = {*lo, *hi};
  std::size_t flat = 0;
  for (double extreme : extremes) {
    std::size_t run = 0;
    for (std::size_t i = 0; i <= x.size(); ++i) {
      if (i < x.size() && x[i] == extreme) {
        ++run;
        continue;
      }
      if (run >= kClipRunSamples) flat += run;
      run = 0;
    }
    if (extremes[0] == extremes[1]) break;  // a constant signal: count it once
  }
  return flat;
}

void check_range(CheckTally& tally, const LoadedRecording& r, const char* name, double low, double high,
                 double peak_at_least, const char* units, double& seen_lo, double& seen_hi) {
  const Signal& s = r.signals.at(name);
  if (!s.ok()) {
    tally.skip(r.path + "/" + name + " " + s.problem);
    return;
  }
  double lo = INFINITY, hi = -INFINITY;
  for (double v : s.values)
    if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  if (!std::isfinite(lo)) {
    tally.skip(r.path + "/" + name + " has no finite value");
    return;
  }
  seen_lo = std::min(seen_lo, lo);
  seen_hi = std::max(seen_hi, hi);
  const std::string range = "ranges " + number(lo, 4) + " .. " + number(hi, 4) + " " + units;
  if (lo < low) tally.fail(r.path + "/" + name, range + ", below " + number(low, 4) + " " + units);
  else if (hi > high) tally.fail(r.path + "/" + name, range + ", above " + number(high, 4) + " " + units);
  else if (hi < peak_at_least)
    tally.fail(r.path + "/" + name, range + ", never reaching " + number(peak_at_least, 4) + " " + units);
  else tally.pass();
}

// Per 100 ms window, the energy of accel over that of the three axes (quiet windows left out).
std::vector<std::pair<std::size_t, double>> reduction_ratios(const Signal& accel, const Signal& xyz) {
  const std::size_t n = std::min(accel.rows, xyz.rows), w = kReductionWindowSamples;
  std::vector<std::pair<std::size_t, double>> ratios;
  std::vector<double> axes;
  for (std::size_t s = 0; s + w <= n; s += w) {
    double sum = 0;
    for (std::size_t i = s; i < s + w; ++i)
      for (std::size_t c = 0; c < 3; ++c) sum += xyz.at(i, c) * xyz.at(i, c);
    axes.push_back(sum);
  }
  double mean = 0;
  for (double e : axes) mean += e / double(std::max<std::size_t>(1, axes.size()));
  for (std::size_t k = 0; k < axes.size(); ++k) {
    if (!(axes[k] > kReductionQuiet * mean)) continue;
    double sum = 0;
    for (std::size_t i = k * w; i < (k + 1) * w; ++i) sum += accel.at(i) * accel.at(i);
    ratios.emplace_back(k * w, sum / axes[k]);
  }
  return ratios;
}

}  // namespace

SignalChecks::SignalChecks()
    : nan_("signal.nan", "recordings"),
      rate_("signal.sample_rate", "recordings"),
      duration_("signal.duration", "recordings"),
      short_("signal.short", "recordings"),
      clipping_("signal.clipping", "acceleration channels"),
      force_("signal.force_range", "recordings"),
      speed_("signal.speed_range", "recordings"),
      spectrum_("signal.accel_spectrum", "recordings"),
      reduction_("signal.reduction_energy", "recordings") {}

void SignalChecks::add(const LoadedRecording& r) {
  // NaN / Inf in any signal.
  std::size_t readable = 0;
  std::string bad;
  for (const auto& [name, s] : r.signals) {
    if (!s.ok()) continue;
    ++readable;
    const auto it = std::find_if(s.values.begin(), s.values.end(), [](double v) { return !std::isfinite(v); });
    if (it != s.values.end() && bad.empty()) {
      const std::size_t index = std::size_t(it - s.values.begin());
      const auto count = std::count_if(s.values.begin(), s.values.end(), [](double v) { return !std::isfinite(v); });
      bad = name + " has " + std::to_string(count) + " NaN/Inf values, the first at sample " +
            std::to_string(index / s.columns) + " (" + number(*it, 4) + ")";
    }
  }
  if (!bad.empty()) nan_.fail(r.path, bad);
  else if (readable) nan_.pass();
  else nan_.skip(r.path + ": no readable signal");

  // Sample rate.
  if (!r.sample_rate_hz) rate_.skip(r.path + ": no sample_rate_hz attribute");
  else if (std::abs(*r.sample_rate_hz - kSampleRateHz) > 1e-6 * kSampleRateHz)
    rate_.fail(r.path, "sample_rate_hz is " + number(*r.sample_rate_hz, 8) + ", expected " + number(kSampleRateHz, 8));
  else rate_.pass();

  // Duration: consistent with the file's own rate, and at least one model window.
  if (!r.samples || !r.duration_s || !r.sample_rate_hz || *r.sample_rate_hz <= 0) {
    duration_.skip(r.path + ": samples, duration_s or sample_rate_hz missing");
    short_.skip(r.path + ": no samples attribute");
  } else {
    const double expected = double(*r.samples) / *r.sample_rate_hz;
    if (std::abs(*r.duration_s - expected) > 0.5 / *r.sample_rate_hz)
      duration_.fail(r.path, "duration_s is " + number(*r.duration_s, 8) + " s, but " + std::to_string(*r.samples) +
                                 " samples at " + number(*r.sample_rate_hz, 8) + " Hz last " + number(expected, 8) + " s");
    else if (*r.samples < std::int64_t(kWindowSpan))
      duration_.fail(r.path, std::to_string(*r.samples) + " samples, fewer than one model window (" +
                                 std::to_string(kWindowSpan) + ")");
    else duration_.pass();
    if (*r.samples < std::int64_t(kShortRecordingSamples))
      short_.fail(r.path, std::to_string(*r.samples) + " samples (" + number(expected, 3) + " s): a " +
                              std::to_string(kDefaultSections) + "-section split leaves sections too short for a window");
    else short_.pass();
  }

  // Clipping of the acceleration axes and their DFT321 reduction.
  const Signal& xyz = r.signals.at("accel_xyz");
  const Signal& accel = r.signals.at("accel");
  std::vector<std::pair<std::string, std::vector<double>>> channels;
  if (xyz.ok())
    for (std::size_t c = 0; c < 3; ++c) channels.emplace_back("accel_xyz[:, " + std::to_string(c) + "]", xyz.column(c));
  if (accel.ok()) channels.emplace_back("accel", accel.values);
  if (channels.empty()) clipping_.skip(r.path + ": no readable acceleration");
  for (const auto& [name, x] : channels) {
    const std::size_t flat = flat_top_samples(x);
    worst_clip_share_ = std::max(worst_clip_share_, double(flat) / double(std::max<std::size_t>(1, x.size())));
    if (double(flat) > kClipMaxShare * double(x.size()))
      clipping_.fail(r.path + "/" + name.substr(0, name.find('[')),
                     name + ": " + std::to_string(flat) + " of " + std::to_string(x.size()) +
                         " samples in flat tops at its extremes (" + number(100.0 * double(flat) / double(x.size()), 3) +
                         "%, at most " + number(100 * kClipMaxShare, 4) + "%)");
    else clipping_.pass();
  }

  // DFT321 keeps each window's energy.
  if (!accel.ok() || !xyz.ok()) {
    reduction_.skip(r.path + ": accel or accel_xyz unreadable");
  } else {
    std::pair<std::size_t, double> worst{0, 1.0};
    for (const auto& [start, ratio] : reduction_ratios(accel, xyz)) {
      reduction_lo_ = std::min(reduction_lo_, ratio);
      reduction_hi_ = std::max(reduction_hi_, ratio);
      if (!(std::abs(std::log(ratio)) <= std::abs(std::log(worst.second)))) worst = {start, ratio};
    }
    if (!(worst.second >= kReductionEnergyLow && worst.second <= kReductionEnergyHigh))
      reduction_.fail(r.path + "/accel", "the 100 ms window at sample " + std::to_string(worst.first) + " holds " +
                                             number(worst.second, 3) + " x the energy of the three axes (0.8 to 1.25 expected)");
    else reduction_.pass();
  }

  check_range(force_, r, "force_normal", kForceMinN, kForceMaxN, kForcePeakAtLeastN, "N", force_lo_, force_hi_);
  check_range(speed_, r, "speed", kSpeedMinMmS, kSpeedMaxMmS, kSpeedPeakAtLeastMmS, "mm/s", speed_lo_, speed_hi_);

  // Acceleration band 100 Hz .. 1 kHz.
  if (!accel.ok()) {
    spectrum_.skip(r.path + "/accel " + accel.problem);
  } else {
    const BandPower p = band_power(accel.values, r.analysis_rate(), kAccelBandLowHz, kAccelBandHighHz);
    const double rms = std::sqrt(p.band);
    if (std::isfinite(p.total)) lowest_band_share_ = std::min(lowest_band_share_, p.share());
    if (!std::isfinite(p.total)) spectrum_.skip(r.path + "/accel is not finite");
    else if (p.share() < kAccelBandMinShare || rms < kAccelBandMinRms)
      spectrum_.fail(r.path + "/accel", "100-1000 Hz holds " + number(100 * p.share(), 3) + "% of the power (" +
                                            number(rms, 3) + " m/s^2 RMS); at least " + number(100 * kAccelBandMinShare, 4) +
                                            "% and " + number(kAccelBandMinRms, 4) + " m/s^2 expected");
    else spectrum_.pass();
  }
}

std::vector<CheckResult> SignalChecks::results() const {
  CheckTally clipping = clipping_, force = force_, speed = speed_, spectrum = spectrum_, reduction = reduction_;
  reduction.set_pass_message("every 100 ms window of accel holds " + number(reduction_lo_, 3) + " to " + number(reduction_hi_, 3) +
                             " x the axes' energy");
  clipping.set_pass_message("at most " + number(100 * worst_clip_share_, 3) + "% of any channel's samples in flat tops");
  force.set_pass_message("force_normal ranges " + number(force_lo_, 4) + " .. " + number(force_hi_, 4) + " N");
  speed.set_pass_message("speed ranges " + number(speed_lo_, 4) + " .. " + number(speed_hi_, 4) + " mm/s");
  spectrum.set_pass_message("100-1000 Hz holds at least " + number(100 * lowest_band_share_, 3) + "% of the power");
  return {nan_.result(),      rate_.result(),  duration_.result(), short_.result(),
          clipping.result(),  force.result(),  speed.result(),     spectrum.result(), reduction.result()};
}

}  // namespace haptex::qa
