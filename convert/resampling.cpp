#include "convert/resampling.hpp"

#include <algorithm>
#include <cmath>

#include "convert/recording_checks.hpp"
#include "core/error.hpp"
#include "core/signal/resample.hpp"
#include "core/text/format.hpp"

namespace haptex::convert {
namespace {

constexpr int kRateHz = int(kSampleRateHz);

std::string rate_text(const std::vector<StampedChannels>& groups) {
  std::string text;
  for (const auto& g : groups) text += (text.empty() ? "" : "; ") + g.time_column + " " + std::to_string(g.nominal_hz) + " Hz";
  return text;
}

}  // namespace

int whole_source_rate(const std::string& file, const std::string& where, double rate_hz, double lowest_hz, bool stamped) {
  if (rate_hz > kHighestRateHz)
    throw input_error(file, where, text::format("the sample rate is %.4g Hz, over the %.0f Hz haptex takes", rate_hz, kHighestRateHz),
                      "Give the rate in Hz (and times in seconds)");
  const double whole = std::round(rate_hz);
  if (!(rate_hz >= lowest_hz) || std::abs(rate_hz - whole) > 1e-6 * whole)
    throw input_error(file, where,
                      text::format("the sample rate is %.10g Hz; haptex resamples whole numbers of Hz from %.0f Hz up",
                                   rate_hz, lowest_hz),
                      rate_hz < 1 && stamped ? "Give the times in seconds: stamps in milliseconds, microseconds or nanoseconds read as a rate under 1 Hz"
                      : lowest_hz == kLowestAccelRateHz
                          ? "Give the rate in whole Hz, at least 2 kHz for acceleration (the model's spectrum reaches 1000 Hz)"
                          : "Give the rate in whole Hz");
  return int(whole);
}

double check_stamps(const std::string& file, const std::string& column, const std::vector<double>& t,
                    const std::vector<std::size_t>& lines, bool* uniform) {
  const std::string where = "column '" + column + "'";
  if (t.size() < 2) throw input_error(file, where, "holds fewer than two samples", "Give one row per sample");
  // Stamps so large that a double no longer holds their steps (1e12 s keeps steps of 0.12 ms) were read
  // already rounded, and would be resampled on the wrong times (review 14, F4).
  const double largest = std::max(std::abs(t.front()), std::abs(t.back())), kept = std::nextafter(largest, INFINITY) - largest;
  if (const double apart = (t.back() - t.front()) / double(t.size() - 1); apart > 0 && kept > 1e-3 * apart)
    throw input_error(file, where,
                      text::format("the time stamps reach %.6g s, where a number keeps steps of %.2g s only, too coarse for samples "
                                   "%.3g s apart",
                                   largest, kept, apart),
                      "Give the times in seconds from the recording's start (subtract the first stamp)");
  std::vector<double> steps;
  for (std::size_t i = 1; i < t.size(); ++i) {
    if (!(t[i] > t[i - 1]))
      throw input_error(file, "line " + std::to_string(lines[i]) + ", " + where,
                        text::format("the time %.9g s does not come after the one before (%.9g s)", t[i], t[i - 1]),
                        "Remove repeated or out-of-order rows");
    steps.push_back(t[i] - t[i - 1]);
  }
  std::vector<double> sorted = steps;
  std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(sorted.size() / 2), sorted.end());
  const double median = sorted[sorted.size() / 2], mean = (t.back() - t.front()) / double(steps.size());
  if (uniform) *uniform = true;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    if (steps[i] > 3 * median)
      throw input_error(file, "line " + std::to_string(lines[i + 1]) + ", " + where,
                        text::format("a gap of %.6f s where samples come every %.6f s: samples were dropped or the "
                                     "clock jumped",
                                     steps[i], median),
                        "Convert the parts before and after the gap as separate recordings");
    if (uniform) *uniform = *uniform && std::abs(steps[i] - mean) <= 0.01 * mean;
  }
  if (1.0 / mean > kHighestRateHz)
    throw input_error(file, where,
                      text::format("the time stamps are %.3g s apart on average (%.4g Hz), over the %.0f Hz haptex takes", mean,
                                   1.0 / mean, kHighestRateHz),
                      "Give the times in seconds");
  return 1.0 / mean;
}

void resample_uniform(Recording& recording, int source_hz) {
  if (source_hz == kRateHz) return;
  const signal::PolyResampler resample(kRateHz, source_hz);
  for (auto& [channel, values] : recording.channels) values = resample(values);
  recording.sample_rate_hz = kSampleRateHz;
  recording.source_texts["resampled"] =
      text::format("from %d Hz by resample_poly (scipy semantics, padtype mean; docs/convert.md)", source_hz);
}

void resample_stamped(Recording& recording, const std::vector<StampedChannels>& groups) {
  double start = -INFINITY, end = INFINITY;
  for (const auto& g : groups) {
    start = std::max(start, g.times.front());
    end = std::min(end, g.times.back());
  }
  const double span = end - start;
  if (!(span * kSampleRateHz + 1 >= double(kMinimumSamples)))
    throw input_error(recording.source_path, "time columns " + rate_text(groups),
                      text::format("the channels' time stamps overlap for %.4g s", std::max(0.0, span)),
                      "A recording needs 0.1 s that every channel covers");
  std::size_t n = std::size_t(std::floor(span * kSampleRateHz)) + 1;
  for (const auto& g : groups) {
    const std::size_t count = std::size_t(std::floor(span * g.nominal_hz)) + 1;
    const signal::PolyResampler resample(kRateHz, g.nominal_hz);
    for (const auto& channel : g.channels) {
      std::vector<double>& values = recording.channels.at(channel);
      values = resample(signal::interpolate_uniform(g.times, values, start, g.nominal_hz, count));
      n = std::min(n, values.size());
    }
  }
  // Each rate's grid rounds the span its own way: all channels end at the shortest.
  for (auto& [channel, values] : recording.channels) values.resize(n);
  recording.sample_rate_hz = kSampleRateHz;
  recording.source_texts["resampled"] = "from time stamps (" + rate_text(groups) +
                                        ") by numpy.interp at those rates, then resample_poly (scipy semantics, padtype "
                                        "mean; docs/convert.md)";
}

}  // namespace haptex::convert
