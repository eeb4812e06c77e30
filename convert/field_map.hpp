#pragma once
// Where each channel lives in a user's HaTT recorded-data XML or CSV (schemas/hatt-recording-map.json).
#include <map>
#include <string>

namespace haptex::convert {

struct FieldMap {
  std::string root, material, texture_attribute, sample_rate, value, csv_time_column;
  std::map<std::string, std::string> units;     // quantity -> element name
  std::map<std::string, std::string> channels;  // canonical channel -> element / column name
  std::map<std::string, std::string> csv_channel_times;  // canonical channel -> its own CSV time column
  std::map<std::string, std::string> csv_units;          // quantity -> the unit of its CSV columns
  std::string origin;                           // "built-in default" or the map file's path
};

// The map compiled into haptex (schemas/hatt-recording-map.json).
FieldMap default_field_map();
// A user's map file, validated against schemas/hatt-recording-map.schema.json.
FieldMap load_field_map(const std::string& path);

}  // namespace haptex::convert
