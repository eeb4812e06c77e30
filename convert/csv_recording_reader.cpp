#include "convert/csv_recording_reader.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>

#include "convert/csv_table.hpp"
#include "convert/recording_checks.hpp"
#include "convert/resampling.hpp"
#include "core/error.hpp"
#include "core/text/format.hpp"
#include "core/text/utf8.hpp"

namespace haptex::convert {

namespace {

// A channel's values and its time column's stamps in the same rows: a value without its time, or a time
// without its value, would pair every later sample with the wrong stamp.
void require_same_rows(const std::string& path, const CsvTable& table, const std::string& column, const std::string& time) {
  const auto& values = table.lines.at(column);
  const auto& stamps = table.lines.at(time);
  const auto [v, t] = std::mismatch(values.begin(), values.end(), stamps.begin(), stamps.end());
  if (v == values.end() && t == stamps.end()) return;
  const bool value_alone = t == stamps.end() || (v != values.end() && *v < *t);
  const std::size_t line = value_alone ? *v : *t;
  throw input_error(path, "line " + std::to_string(line),
                    value_alone ? "column '" + column + "' has a value but its time column '" + time + "' is empty"
                                : "time column '" + time + "' has a time but column '" + column + "' is empty",
                    "Give each sample its time in the same row, and leave both cells empty where there is none");
}

// The time column of each channel present, with its channels and stamps.
std::vector<StampedChannels> group_by_time(const std::string& path, const FieldMap& map, const Recording& recording,
                                           CsvTable& table) {
  std::map<std::string, StampedChannels> groups;
  for (const auto& [channel, values] : recording.channels) {
    auto own = map.csv_channel_times.find(channel);
    const std::string& time = own == map.csv_channel_times.end() ? map.csv_time_column : own->second;
    StampedChannels& g = groups[time];
    g.time_column = time;
    g.channels.push_back(channel);
  }
  std::vector<StampedChannels> out;
  for (auto& [time, g] : groups) {
    auto column = table.columns.find(time);
    if (column == table.columns.end())
      throw input_error(path, "line 1", "the header has no '" + time + "' column",
                        "Add a time column in seconds named " + time + " (the field map's csv_time_column or csv_channel_times)");
    g.times = std::move(column->second);
    for (const auto& channel : g.channels) {
      require_same_rows(path, table, map.channels.at(channel), time);
      if (recording.channels.at(channel).size() != g.times.size())
        throw input_error(path, "column '" + map.channels.at(channel) + "'",
                          "has " + std::to_string(recording.channels.at(channel).size()) + " values but its time column '" +
                              time + "' has " + std::to_string(g.times.size()),
                          "Give each sample its time in the same row, and leave both cells empty where there is none");
    }
    out.push_back(std::move(g));
  }
  return out;
}

// The stamps' rate in whole Hz (acceleration needs kLowestAccelRateHz).
int stamped_rate(const std::string& path, const StampedChannels& g, const std::vector<std::size_t>& lines, bool& uniform) {
  const double rate = check_stamps(path, g.time_column, g.times, lines, &uniform);
  const bool accel = std::any_of(g.channels.begin(), g.channels.end(), [](const std::string& c) { return quantity_of(c) == "accel"; });
  return whole_source_rate(path, "column '" + g.time_column + "'", std::round(rate), accel ? kLowestAccelRateHz : kLowestRateHz, true);
}

}  // namespace

std::string material_from_file_stem(const std::string& stem) {
  const auto separator = stem.find_last_of("_-");
  if (separator == std::string::npos || separator + 1 == stem.size()) return stem;
  const std::string tail = stem.substr(separator + 1);
  const bool numbered = std::all_of(tail.begin(), tail.end(), [](unsigned char c) { return std::isdigit(c); });
  return numbered && separator > 0 ? stem.substr(0, separator) : stem;
}

// A channel's own clock spans about what the main one does (review 10, F8: a channel column in
// milliseconds beside a main one in seconds was taken, and the overlap kept the channel's first 2 ms
// stretched over the recording). Its rows need not be the main clock's instants (a slower log may fill
// the first rows), and it may start earlier or end later; but a span 100 times the main one's, or a
// hundredth of it, is another unit: milliseconds give 1000.
void require_comparable_span(const std::string& path, const StampedChannels& main, const StampedChannels& own) {
  const double main_span = main.times.back() - main.times.front(), own_span = own.times.back() - own.times.front();
  if (!(main_span > 0) || !(own_span > 0)) return;
  const double ratio = own_span / main_span;
  if (ratio <= 100 && ratio >= 0.01) return;
  throw input_error(path, "column '" + own.time_column + "'",
                    text::format("its times span %.6g s, %.4g times the %.6g s of column '%s'", own_span, ratio, main_span,
                                 main.time_column.c_str()),
                    "Give every time column in seconds (stamps in milliseconds span 1000 times as much)");
}

Recording read_csv_recording(const std::string& path, const FieldMap& map, std::uintmax_t max_bytes) {
  Recording recording;
  recording.source_path = path;
  recording.material = material_from_file_stem(std::filesystem::path(path).stem().string());
  text::require_utf8(recording.material, path, "the material name (the file's name)");
  std::map<std::string, std::string> channel_of;  // column name -> channel
  for (const auto& [channel, name] : map.channels) channel_of[name] = channel;
  std::set<std::string> times = {map.csv_time_column}, sparse;
  for (const auto& [channel, time] : map.csv_channel_times) {
    times.insert(time);
    sparse.insert(time);
    if (auto name = map.channels.find(channel); name != map.channels.end()) sparse.insert(name->second);
  }
  CsvTable table = read_csv_table(
      path, max_bytes, [&](const std::string& name) { return times.count(name) > 0 || channel_of.count(name) > 0; },
      [&](const std::string& name) { return sparse.count(name) > 0; });
  recording.source_sha256 = table.sha256;
  for (const auto& [channel, name] : map.channels) {
    if (auto column = table.columns.find(name); column != table.columns.end())
      recording.channels[channel] = std::move(column->second);
    else if (is_required_channel(channel))
      throw input_error(path, "line 1", "the header has no '" + name + "' column (" + channel + ")",
                        "Add the column, or map \"" + channel + "\" to your column's name in a field map (--map)");
  }
  std::vector<StampedChannels> timed = group_by_time(path, map, recording, table);
  const auto main = std::find_if(timed.begin(), timed.end(), [&](const StampedChannels& g) { return g.time_column == map.csv_time_column; });
  for (const StampedChannels& g : timed)
    if (main != timed.end() && &g != &*main) require_comparable_span(path, *main, g);
  bool all_uniform = true;
  for (auto& g : timed) {
    bool uniform = false;
    g.nominal_hz = stamped_rate(path, g, table.lines.at(g.time_column), uniform);
    all_uniform = all_uniform && uniform;
  }
  recording.sample_rate_hz = timed.front().nominal_hz;
  // Channels sampled together at a steady rate keep their samples (10 kHz) or are resampled as they
  // are; stamps that wander, or channels of their own times, go onto one grid.
  if (timed.size() == 1 && all_uniform) resample_uniform(recording, timed.front().nominal_hz);
  else resample_stamped(recording, timed);
  for (const auto& [quantity, unit] : kExpectedUnits) recording.units[quantity] = unit;
  for (const auto& [quantity, unit] : map.csv_units) apply_units(recording, quantity, unit, "csv_units of " + map.origin);
  check_channels(recording, [&](const std::string& channel) {
    auto it = map.channels.find(channel);
    return "column '" + (it == map.channels.end() ? channel : it->second) + "'";
  });
  return recording;
}

}  // namespace haptex::convert
