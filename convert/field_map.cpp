#include "convert/field_map.hpp"

#include <nlohmann/json.hpp>

#include "core/embedded.hpp"
#include "core/json/schema.hpp"

namespace haptex::convert {
namespace {

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
