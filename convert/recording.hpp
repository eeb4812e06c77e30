#pragma once
// One vibration recording as read from a HaTT recorded-data XML or a CSV file, before it is
// turned into the recordings file (docs/convert.md; schemas/hdf5-layout.md).
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "dataset/layout.hpp"
#include "dataset/window.hpp"

namespace haptex::convert {

// Canonical channel names. Required: accel_x/y/z, force_normal, speed.
// Optional: force_tangential, position_x/y/z (all three or none).
// Channels that become one dataset each take that dataset's name (dataset/layout.hpp).
inline const std::vector<std::string> kRequiredChannels = {"accel_x", "accel_y", "accel_z", dataset::layout::kForceNormal,
                                                           dataset::layout::kSpeed};
bool is_required_channel(const std::string& channel);

struct Recording {
  std::string material;       // the surface's name as the file gives it
  std::optional<int> texture; // HaTT texture number, when the file has one
  double sample_rate_hz = 0;
  std::map<std::string, std::string> units;  // "accel", "force", "speed", "position"
  std::map<std::string, std::vector<double>> channels;
  std::string source_path;
  std::string source_sha256;
  // More attributes the source states (schemas/hdf5-layout.md): a Cluster take's conditions and its
  // other files, by their names in dataset/layout.hpp.
  std::map<std::string, double> source_numbers;
  std::map<std::string, std::string> source_texts;

  std::size_t samples() const { return channels.empty() ? 0 : channels.begin()->second.size(); }
  bool has(const std::string& channel) const { return channels.count(channel) > 0; }
};

using dataset::kSampleRateHz;  // the only rate haptex keeps; sources at other rates are refused
// What each quantity must be measured in (docs/architecture.md, "Signals and conventions").
inline const std::map<std::string, std::string> kExpectedUnits = {
    {"accel", "m/s^2"}, {"force", "N"}, {"speed", "mm/s"}, {"position", "mm"}};

// The quantity a channel measures: accel_x -> accel, force_normal -> force, ...
std::string quantity_of(const std::string& channel);

}  // namespace haptex::convert
