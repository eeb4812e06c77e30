#pragma once
// CSV recordings from users' own rigs: one header row naming the field map's channel names
// (accelX, accelY, ... as in the XML) plus the time column (time_s); one row per sample at 10 kHz.
// Values are in haptex units (m/s^2, N, mm/s, mm). The material is the file name without a
// trailing recording number: "Cork_2.csv" -> "Cork".
#include <cstdint>
#include <string>

#include "convert/field_map.hpp"
#include "convert/input_limits.hpp"
#include "convert/recording.hpp"

namespace haptex::convert {

Recording read_csv_recording(const std::string& path, const FieldMap& map, std::uintmax_t max_bytes = kDefaultMaxBytes);

// "Cork_2" -> "Cork", "Brick 2" -> "Brick 2" (a number after a space is part of the name).
std::string material_from_file_stem(const std::string& stem);

}  // namespace haptex::convert
