#pragma once
// HaTT recorded-data XML (docs/convert.md), read through a field map.
#include <cstdint>
#include <string>

#include "convert/field_map.hpp"
#include "convert/input_limits.hpp"
#include "convert/recording.hpp"

namespace haptex::convert {

// Throws haptex::Error (bad_input) naming the file, the element and line, and the fix, for:
// a file over max_bytes, malformed or truncated XML, a DTD or entity declaration (refused:
// no entity expansion), a missing element or channel, a value that is not a finite number,
// channels of different lengths, and a missing or wrong sample rate or unknown units.
Recording read_hatt_recording_xml(const std::string& path, const FieldMap& map,
                                  std::uintmax_t max_bytes = kDefaultMaxBytes);

}  // namespace haptex::convert
