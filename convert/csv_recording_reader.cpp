#include "convert/csv_recording_reader.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "convert/csv_table.hpp"
#include "convert/recording_checks.hpp"
#include "core/error.hpp"
#include "core/text/utf8.hpp"

namespace haptex::convert {

namespace {

double sample_rate_from_times(const std::string& path, const std::string& column, const std::vector<double>& t) {
  if (t.size() < 2) return 0;
  const double dt = (t.back() - t.front()) / double(t.size() - 1);
  for (std::size_t i = 1; i < t.size(); ++i)
    if (std::abs((t[i] - t[i - 1]) - dt) > 0.01 * std::abs(dt))
      throw input_error(path, "line " + std::to_string(i + 2) + ", column '" + column + "'",
                        "the time step is " + std::to_string(t[i] - t[i - 1]) + " s, not the file's mean " +
                            std::to_string(dt) + " s: samples were dropped or the clock jumped",
                        "Resample the recording onto a uniform 10 kHz time base");
  return dt > 0 ? 1.0 / dt : 0;
}

}  // namespace

std::string material_from_file_stem(const std::string& stem) {
  const auto separator = stem.find_last_of("_-");
  if (separator == std::string::npos || separator + 1 == stem.size()) return stem;
  const std::string tail = stem.substr(separator + 1);
  const bool numbered = std::all_of(tail.begin(), tail.end(), [](unsigned char c) { return std::isdigit(c); });
  return numbered && separator > 0 ? stem.substr(0, separator) : stem;
}

Recording read_csv_recording(const std::string& path, const FieldMap& map, std::uintmax_t max_bytes) {
  Recording recording;
  recording.source_path = path;
  recording.material = material_from_file_stem(std::filesystem::path(path).stem().string());
  text::require_utf8(recording.material, path, "the material name (the file's name)");
  std::map<std::string, std::string> channel_of;  // column name -> channel
  for (const auto& [channel, name] : map.channels) channel_of[name] = channel;
  CsvTable table = read_csv_table(path, max_bytes, [&](const std::string& name) {
    return name == map.csv_time_column || channel_of.count(name) > 0;
  });
  recording.source_sha256 = table.sha256;
  if (!table.columns.count(map.csv_time_column))
    throw input_error(path, "line 1", "the header has no '" + map.csv_time_column + "' column",
                      "Add a time column in seconds named " + map.csv_time_column);
  for (const auto& [channel, name] : map.channels) {
    if (auto column = table.columns.find(name); column != table.columns.end())
      recording.channels[channel] = std::move(column->second);
    else if (is_required_channel(channel))
      throw input_error(path, "line 1", "the header has no '" + name + "' column (" + channel + ")",
                        "Add the column, or map \"" + channel + "\" to your column's name in a field map (--map)");
  }
  const std::vector<double>& times = table.columns.at(map.csv_time_column);
  check_channels(recording, [&](const std::string& channel) {
    auto it = map.channels.find(channel);
    return "column '" + (it == map.channels.end() ? channel : it->second) + "'";
  });
  recording.sample_rate_hz = sample_rate_from_times(path, map.csv_time_column, times);
  check_sample_rate(path, "column '" + map.csv_time_column + "'", recording.sample_rate_hz);
  for (const auto& [quantity, unit] : kExpectedUnits) recording.units[quantity] = unit;
  return recording;
}

}  // namespace haptex::convert
