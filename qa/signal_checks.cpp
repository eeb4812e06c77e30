// signal.*: NaN/Inf, sample rate, duration, clipping, physical force and speed, acceleration band,
// energy kept by the DFT321 reduction; one recording per call (docs/qa.md, "Recordings").
#include <algorithm>
#include <cmath>

#include "dataset/layout.hpp"
#include "qa/band_power.hpp"
#include "qa/recording_checks.hpp"
#include "qa/thresholds.hpp"

namespace haptex::qa {

namespace layout = dataset::layout;
namespace {

// "NAME has N NaN/Inf values, the first at ..."; empty when every value is finite.
std::string non_finite_values(const std::string& name, const Signal& s) {
  const auto not_finite = [](double v) { return !std::isfinite(v); };
  const auto it = std::find_if(s.values.begin(), s.values.end(), not_finite);
  if (it == s.values.end()) return "";
  const std::size_t index = std::size_t(it - s.values.begin());
  const auto count = std::count_if(s.values.begin(), s.values.end(), not_finite);
  return name + " has " + std::to_string(count) + " NaN/Inf values, the first at sample " +
         std::to_string(index / s.columns) + " (" + number(*it, 4) + ")";
}

// signal.duration and signal.short need the samples, the duration and a positive rate.
bool has_timing(const LoadedRecording& r) {
  return r.samples && r.duration_s && r.sample_rate_hz && *r.sample_rate_hz > 0;
}

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

// The three axes and their reduction, by name.
std::vector<std::pair<std::string, std::vector<double>>> acceleration_channels(const LoadedRecording& r) {
  const Signal& xyz = r.signals.at(layout::kAccelXyz);
  const Signal& accel = r.signals.at(layout::kAccel);
  std::vector<std::pair<std::string, std::vector<double>>> channels;
  if (xyz.ok())
    for (std::size_t c = 0; c < 3; ++c) channels.emplace_back("accel_xyz[:, " + std::to_string(c) + "]", xyz.column(c));
  if (accel.ok()) channels.emplace_back(layout::kAccel, accel.values);
  return channels;
}

// The physical range of a raw signal (signal.force_range, signal.speed_range).
struct Range {
  const char* name;
  double low, high, peak_at_least;
  const char* units;
};

void check_range(const LoadedRecording& r, const Range& range, CheckTally& tally, Seen& seen) {
  const Signal& s = r.signals.at(range.name);
  const std::string where = r.path + "/" + range.name;
  if (!s.ok()) return tally.skip(where + " " + s.problem);
  Seen here;
  for (double v : s.values)
    if (std::isfinite(v)) here.add(v);
  if (!std::isfinite(here.low)) return tally.skip(where + " has no finite value");
  seen.add(here.low);
  seen.add(here.high);
  const std::string units = std::string(" ") + range.units;
  const std::string ranges = "ranges " + number(here.low, 4) + " .. " + number(here.high, 4) + units;
  if (here.low < range.low) tally.fail(where, ranges + ", below " + number(range.low, 4) + units);
  else if (here.high > range.high) tally.fail(where, ranges + ", above " + number(range.high, 4) + units);
  else if (here.high < range.peak_at_least) tally.fail(where, ranges + ", never reaching " + number(range.peak_at_least, 4) + units);
  else tally.pass();
  tally.set_pass_message(std::string(range.name) + " ranges " + number(seen.low, 4) + " .. " + number(seen.high, 4) + units);
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

void check_signal_nan(const LoadedRecording& r, CheckTally& tally) {
  std::size_t readable = 0;
  std::string bad;
  for (const auto& [name, s] : r.signals) {
    if (!s.ok()) continue;
    ++readable;
    if (bad.empty()) bad = non_finite_values(name, s);
  }
  if (!bad.empty()) tally.fail(r.path, bad);
  else if (readable) tally.pass();
  else tally.skip(r.path + ": no readable signal");
}

void check_signal_sample_rate(const LoadedRecording& r, CheckTally& tally) {
  if (!r.sample_rate_hz) tally.skip(r.path + ": no sample_rate_hz attribute");
  else if (!(std::abs(*r.sample_rate_hz - kSampleRateHz) <= 1e-6 * kSampleRateHz))  // NaN fails too
    tally.fail(r.path, "sample_rate_hz is " + number(*r.sample_rate_hz, 8) + ", expected " + number(kSampleRateHz, 8));
  else tally.pass();
}

// Consistent with the file's own rate, and at least one model window.
void check_signal_duration(const LoadedRecording& r, CheckTally& tally) {
  if (!has_timing(r)) return tally.skip(r.path + ": samples, duration_s or sample_rate_hz missing");
  const double expected = double(*r.samples) / *r.sample_rate_hz;
  if (!(std::abs(*r.duration_s - expected) <= 0.5 / *r.sample_rate_hz))  // NaN fails too
    tally.fail(r.path, "duration_s is " + number(*r.duration_s, 8) + " s, but " + std::to_string(*r.samples) +
                           " samples at " + number(*r.sample_rate_hz, 8) + " Hz last " + number(expected, 8) + " s");
  else if (*r.samples < std::int64_t(kWindowSamples))
    tally.fail(r.path, std::to_string(*r.samples) + " samples, fewer than one model window (" +
                           std::to_string(kWindowSamples) + ")");
  else tally.pass();
}

void check_signal_short(const LoadedRecording& r, CheckTally& tally) {
  if (!has_timing(r)) return tally.skip(r.path + ": no samples attribute");
  if (*r.samples < std::int64_t(kShortRecordingSamples))
    tally.fail(r.path, std::to_string(*r.samples) + " samples (" + number(double(*r.samples) / *r.sample_rate_hz, 3) +
                           " s): a " + std::to_string(kDefaultSections) +
                           "-section split leaves sections too short for a window");
  else tally.pass();
}

void check_signal_clipping(const LoadedRecording& r, CheckTally& tally, Seen& flat_share) {
  const auto channels = acceleration_channels(r);
  if (channels.empty()) return tally.skip(r.path + ": no readable acceleration");
  for (const auto& [name, x] : channels) {
    const std::size_t flat = flat_top_samples(x);
    flat_share.add(double(flat) / double(std::max<std::size_t>(1, x.size())));
    if (double(flat) > kClipMaxShare * double(x.size()))
      tally.fail(r.path + "/" + name.substr(0, name.find('[')),
                 name + ": " + std::to_string(flat) + " of " + std::to_string(x.size()) +
                     " samples in flat tops at its extremes (" + number(100.0 * double(flat) / double(x.size()), 3) +
                     "%, at most " + number(100 * kClipMaxShare, 4) + "%)");
    else tally.pass();
  }
  tally.set_pass_message("at most " + number(100 * flat_share.high, 3) + "% of any channel's samples in flat tops");
}

void check_signal_force_range(const LoadedRecording& r, CheckTally& tally, Seen& force) {
  check_range(r, {layout::kForceNormal, kForceMinN, kForceMaxN, kForcePeakAtLeastN, "N"}, tally, force);
}

void check_signal_speed_range(const LoadedRecording& r, CheckTally& tally, Seen& speed) {
  check_range(r, {layout::kSpeed, kSpeedMinMmS, kSpeedMaxMmS, kSpeedPeakAtLeastMmS, "mm/s"}, tally, speed);
}

void check_signal_accel_spectrum(const LoadedRecording& r, CheckTally& tally, Seen& band_share) {
  const Signal& accel = r.signals.at(layout::kAccel);
  if (!accel.ok()) return tally.skip(r.path + "/accel " + accel.problem);
  const BandPower p = band_power(accel.values, r.analysis_rate(), kAccelBandLowHz, kAccelBandHighHz);
  if (!std::isfinite(p.total)) return tally.skip(r.path + "/accel is not finite");
  band_share.add(p.share());
  const double rms = std::sqrt(p.band);
  if (p.share() < kAccelBandMinShare || rms < kAccelBandMinRms)
    tally.fail(r.path + "/accel", "100-1000 Hz holds " + number(100 * p.share(), 3) + "% of the power (" +
                                      number(rms, 3) + " m/s^2 RMS); at least " + number(100 * kAccelBandMinShare, 4) +
                                      "% and " + number(kAccelBandMinRms, 4) + " m/s^2 expected");
  else tally.pass();
  tally.set_pass_message("100-1000 Hz holds at least " + number(100 * band_share.low, 3) + "% of the power");
}

// Judged by the window furthest from the axes' energy (on a log scale: half and double are as far).
void check_signal_reduction_energy(const LoadedRecording& r, CheckTally& tally, Seen& energy_ratio) {
  const Signal& accel = r.signals.at(layout::kAccel);
  const Signal& xyz = r.signals.at(layout::kAccelXyz);
  if (!accel.ok() || !xyz.ok()) return tally.skip(r.path + ": accel or accel_xyz unreadable");
  std::pair<std::size_t, double> worst{0, 1.0};
  for (const auto& [start, ratio] : reduction_ratios(accel, xyz)) {
    energy_ratio.add(ratio);
    if (!(std::abs(std::log(ratio)) <= std::abs(std::log(worst.second)))) worst = {start, ratio};
  }
  if (!(worst.second >= kReductionEnergyLow && worst.second <= kReductionEnergyHigh))
    tally.fail(r.path + "/accel", "the 100 ms window at sample " + std::to_string(worst.first) + " holds " +
                                      number(worst.second, 3) + " x the energy of the three axes (0.8 to 1.25 expected)");
  else tally.pass();
  tally.set_pass_message("every 100 ms window of accel holds " + number(energy_ratio.low, 3) + " to " +
                         number(energy_ratio.high, 3) + " x the axes' energy");
}

}  // namespace haptex::qa
