#include "convert/recording_checks.hpp"

#include <cmath>

#include "convert/units.hpp"
#include "core/error.hpp"
#include "core/text/format.hpp"
#include "core/text/parse_number.hpp"

namespace haptex::convert {
void apply_units(Recording& recording, const std::string& quantity, const std::string& unit,
                 const std::string& where) {
  auto scale = unit_scale(quantity, unit);
  if (!scale)
    throw input_error(recording.source_path, where, "unknown " + quantity + " unit '" + unit + "'",
                      "Use one of: " + accepted_units(quantity));
  recording.units[quantity] = kExpectedUnits.at(quantity);
  if (*scale == 1.0) return;
  for (auto& [channel, samples] : recording.channels)
    if (quantity_of(channel) == quantity)
      for (double& v : samples) v *= *scale;
}

void check_channels(const Recording& recording, const std::function<std::string(const std::string&)>& where) {
  const std::string& file = recording.source_path;
  const std::string& first = kRequiredChannels.front();
  const std::size_t n = recording.channels.at(first).size();
  for (const auto& [channel, samples] : recording.channels)
    if (samples.size() != n)
      throw input_error(file, where(channel),
                        "has " + std::to_string(samples.size()) + " samples but " + where(first) + " has " +
                            std::to_string(n),
                        "All channels must be sampled together; re-export the recording or trim the channels "
                        "to the same length");
  if (n < kMinimumSamples)
    throw input_error(file, where(first), "only " + std::to_string(n) + " samples",
                      "A recording needs at least 1000 samples (0.1 s at 10 kHz)");
  // After the units are applied, every sample must still fit the float32 the recordings file stores.
  for (const auto& [channel, samples] : recording.channels)
    for (std::size_t i = 0; i < samples.size(); ++i)
      if (!text::fits_stored_float(samples[i]))  // review 22, F3: 5e-36 mN became the subnormal 5e-39 N
        throw input_error(file, where(channel) + ", sample " + std::to_string(i + 1),
                          text::format(text::within_float_range(samples[i])
                                           ? "%g is under 1.2e-38 but not 0, which the 32-bit floats the recordings file stores keep "
                                             "only with their digits lost"
                                           : "%g is beyond 3.4e38, the largest magnitude of the 32-bit floats the recordings file stores",
                                       samples[i]),
                          "Check the column's unit, or remove the bad samples");
  const int positions = int(recording.has("position_x")) + recording.has("position_y") + recording.has("position_z");
  if (positions != 0 && positions != 3)
    throw input_error(file, where("position_x"), "only some of position x, y, z are present",
                      "Give all three position channels or none");
}


}  // namespace haptex::convert
