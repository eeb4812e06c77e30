#include "convert/field_map.hpp"

#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/embedded.hpp"
#include "core/error.hpp"
#include "core/json/schema.hpp"

namespace haptex::convert {
namespace {

// Review 9, C2: two channels on one column, or a time column that is a channel's, were refused only
// once a CSV was read, naming the CSV and an impossible count instead of the map.
void require_distinct_columns(const FieldMap& map) {
  std::map<std::string, std::string> owner;  // column -> "channels.<channel>"
  for (const auto& [channel, column] : map.channels) {
    const std::string where = "channels." + channel;
    if (const auto [it, fresh] = owner.emplace(column, where); !fresh)
      throw input_error(map.origin, where, "names '" + column + "', as " + it->second + " does", "Give each channel its own element or column");
  }
  std::vector<std::pair<std::string, std::string>> times{{"csv_time_column", map.csv_time_column}};
  for (const auto& [channel, column] : map.csv_channel_times) times.emplace_back("csv_channel_times." + channel, column);
  for (const auto& [where, column] : times)
    if (const auto it = owner.find(column); it != owner.end())
      throw input_error(map.origin, where, "names '" + column + "', the column of " + it->second,
                        "Name the column that holds the time stamps");
}

FieldMap from_json(const nlohmann::json& doc, const std::string& origin) {
  json::validate(doc, "hatt-recording-map.schema.json", origin);
  FieldMap map;
  map.root = doc.at("root");
  map.material = doc.at("material");
  map.texture_attribute = doc.value("texture_attribute", "");
  map.sample_rate = doc.at("sample_rate");
  map.value = doc.at("value");
  map.csv_time_column = doc.at("csv_time_column");
  map.units = doc.at("units").get<std::map<std::string, std::string>>();
  map.channels = doc.at("channels").get<std::map<std::string, std::string>>();
  map.csv_channel_times = doc.value("csv_channel_times", std::map<std::string, std::string>{});
  map.csv_units = doc.value("csv_units", std::map<std::string, std::string>{});
  map.origin = origin;
  require_distinct_columns(map);
  return map;
}

}  // namespace

FieldMap default_field_map() {
  static const FieldMap map =
      from_json(nlohmann::json::parse(embedded::schema("hatt-recording-map.json")), "built-in default map");
  return map;
}

FieldMap load_field_map(const std::string& path) { return from_json(json::read_file(path), path); }

}  // namespace haptex::convert
