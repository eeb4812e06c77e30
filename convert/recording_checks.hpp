#pragma once
// Checks shared by the XML and CSV readers, so both refuse the same things with the same words.
#include <functional>
#include <string>

#include "convert/recording.hpp"
#include "dataset/window.hpp"

namespace haptex::convert {

// Minimum length: one model window.
inline constexpr std::size_t kMinimumSamples = dataset::kWindowSamples;

// Scales a quantity's channels into haptex units; refuses unknown units.
void apply_units(Recording& recording, const std::string& quantity, const std::string& unit,
                 const std::string& where);
// Equal lengths, at least kMinimumSamples, position all-or-none. where(channel) names a channel's
// place in the file for messages ("<accelY> at line 12", "column 'accelY'").
void check_channels(const Recording& recording, const std::function<std::string(const std::string&)>& where);

}  // namespace haptex::convert
