#include "convert/csv_recording_reader.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/text/parse_number.hpp"
#include "convert/recording_checks.hpp"
#include "core/error.hpp"
#include "core/sha256.hpp"
#include "core/text/utf8.hpp"

namespace haptex::convert {

using text::describe_bad_number, text::parse_number, text::trim;
namespace {

std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

// A header cell without white space or surrounding quotes.
std::string column_name(std::string_view cell) {
  cell = trim(cell);
  if (cell.size() >= 2 && cell.front() == '"' && cell.back() == '"') cell = trim(cell.substr(1, cell.size() - 2));
  return std::string(cell);
}

// Walks the buffer line by line with 1-based line numbers.
class Lines {
 public:
  explicit Lines(const std::vector<char>& buffer) : text_(buffer.data(), buffer.size()) {
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") text_.remove_prefix(3);  // UTF-8 byte order mark
  }
  bool next(std::string_view& line) {
    if (position_ >= text_.size()) return false;
    const std::size_t end = std::min(text_.find('\n', position_), text_.size());
    line = text_.substr(position_, end - position_);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    position_ = end + 1;
    ++number_;
    return true;
  }
  std::size_t number() const { return number_; }

 private:
  std::string_view text_;
  std::size_t position_ = 0, number_ = 0;
};

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
  const std::vector<char> buffer = read_whole_file(path, max_bytes);
  Recording recording;
  recording.source_path = path;
  recording.source_sha256 = sha256_hex(buffer);
  recording.material = material_from_file_stem(std::filesystem::path(path).stem().string());
  text::require_utf8(recording.material, path, "the material name (the file's name)");

  Lines lines(buffer);
  std::string_view line;
  if (!lines.next(line))
    throw input_error(path, "line 1", "the file is empty", "Write a header row and one row per sample");
  std::vector<std::string> header;
  for (auto field : split_fields(line)) header.push_back(column_name(field));

  // column index -> channel ("" for the time column, absent for ignored columns)
  std::map<std::size_t, std::string> columns;
  auto column_of = [&](const std::string& name) -> std::optional<std::size_t> {
    auto it = std::find(header.begin(), header.end(), name);
    if (it == header.end()) return std::nullopt;
    return std::size_t(it - header.begin());
  };
  const auto time_column = column_of(map.csv_time_column);
  if (!time_column)
    throw input_error(path, "line 1", "the header has no '" + map.csv_time_column + "' column",
                      "Add a time column in seconds named " + map.csv_time_column);
  for (const auto& [channel, name] : map.channels) {
    if (auto index = column_of(name)) {
      columns[*index] = channel;
      recording.channels[channel];
    } else if (is_required_channel(channel)) {
      throw input_error(path, "line 1", "the header has no '" + name + "' column (" + channel + ")",
                        "Add the column, or map \"" + channel + "\" to your column's name in a field map (--map)");
    }
  }

  std::vector<double> times;
  while (lines.next(line)) {
    if (line.find_first_not_of(" \t") == std::string_view::npos) continue;
    const auto fields = split_fields(line);
    const std::string where = "line " + std::to_string(lines.number());
    if (fields.size() != header.size())
      throw input_error(path, where, "has " + std::to_string(fields.size()) + " fields but the header has " +
                                         std::to_string(header.size()),
                        "Every row needs one value per header column");
    for (std::size_t c = 0; c < fields.size(); ++c) {
      const bool is_time = c == *time_column;
      auto channel = columns.find(c);
      if (!is_time && channel == columns.end()) continue;
      std::optional<double> value = parse_number(fields[c]);
      if (!value || !std::isfinite(*value))
        throw input_error(path, where + ", column '" + header[c] + "'", describe_bad_number(fields[c], value.has_value()),
                          "Remove or interpolate bad samples in the source before converting");
      (is_time ? times : recording.channels[channel->second]).push_back(*value);
    }
  }
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
