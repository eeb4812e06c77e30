#pragma once
// Sources not at 10 kHz (docs/convert.md, "Sources at other rates"): a uniform source at any whole
// number of Hz goes through scipy's resample_poly; channels with their own, possibly irregular,
// time stamps go through numpy.interp at their nominal rate first, onto one grid over the span all
// of them cover (core/signal/resample.hpp).
#include <string>
#include <vector>

#include "convert/recording.hpp"

namespace haptex::convert {

// Acceleration: Nyquist at 1000 Hz, where the model's spectrum ends; slower, it holds none of its top
// bins. Force, speed and position change slowly (the recordings file low-passes them at 20 Hz).
inline constexpr double kLowestAccelRateHz = 2000.0, kLowestRateHz = 1.0;
// Above this, no sensor's rate: the times are likely in another unit than seconds.
inline constexpr double kHighestRateHz = 1e6;

// The rate as a whole number of Hz. Throws haptex::Error (bad_input) naming `file` and `where` for a
// rate under `lowest_hz` or over kHighestRateHz, or one that is no whole number of Hz; `stamped`: the
// rate comes from time stamps (then one under 1 Hz says the times are not in seconds).
int whole_source_rate(const std::string& file, const std::string& where, double rate_hz, double lowest_hz, bool stamped);

// The mean rate of time stamps (seconds) read from `column` of `file`, lines[i] the line of stamp i.
// Throws haptex::Error (bad_input) naming the line: fewer than two stamps, a stamp that does not
// come after the one before, a step over three times the median step (samples dropped: stamps may
// wander, but no interpolation fills a gap), a mean rate over kHighestRateHz. uniform, when given:
// every step within 1 % of the mean.
double check_stamps(const std::string& file, const std::string& column, const std::vector<double>& times,
                    const std::vector<std::size_t>& lines, bool* uniform = nullptr);

// Every channel, sampled together at `source_hz`, to 10 kHz; says so in the recording's `resampled`.
void resample_uniform(Recording& recording, int source_hz);

// Channels that share one time column.
struct StampedChannels {
  std::string time_column;
  std::vector<double> times;  // seconds, strictly increasing
  std::vector<std::string> channels;
  int nominal_hz = 0;  // the grid numpy.interp fills: the stamps' mean rate, whole Hz
};

// Each group's channels (in recording.channels, one value per stamp) onto one 10 kHz grid from the
// latest first stamp to the earliest last one. Throws haptex::Error (bad_input) when the groups
// overlap for less than one model window.
void resample_stamped(Recording& recording, const std::vector<StampedChannels>& groups);

}  // namespace haptex::convert
