#include "capture/device/sensor_catalog.hpp"

#include <nlohmann/json.hpp>

#include "core/embedded.hpp"
#include "core/error.hpp"
#include "core/json/schema.hpp"

namespace haptex::capture {
namespace {

std::regex compile(const std::string& pattern, const std::string& origin, const std::string& where) {
  try {
    return std::regex(pattern, std::regex::ECMAScript);
  } catch (const std::regex_error& e) {
    throw input_error(origin, where, "'" + pattern + "' is not a valid regular expression (" + e.what() + ")",
                      "Write an ECMAScript regular expression");
  }
}

SensorModel model_from(const nlohmann::json& entry, const std::string& origin, std::size_t i) {
  const std::string where = "/sensors/" + std::to_string(i);
  SensorModel m;
  m.model = entry.at("model").get<std::string>();
  m.vendor_id = std::uint16_t(std::stoul(entry.at("vendor_id").get<std::string>(), nullptr, 16));
  m.product_id = std::uint16_t(std::stoul(entry.at("product_id").get<std::string>(), nullptr, 16));
  m.product_pattern = entry.value("product_pattern", "");
  m.serial_pattern = entry.value("serial_pattern", "");
  m.notes = entry.value("notes", "");
  if (!m.product_pattern.empty()) m.product_regex = compile(m.product_pattern, origin, where + "/product_pattern");
  if (!m.serial_pattern.empty()) {
    m.serial_regex = compile(m.serial_pattern, origin, where + "/serial_pattern");
    if (m.serial_regex.mark_count() < 1)
      throw input_error(origin, where + "/serial_pattern", "the pattern has no (group) around the serial",
                        "Put parentheses around the part of the product string that is the serial");
  }
  return m;
}

}  // namespace

SensorCatalog SensorCatalog::parse(const std::string& text, const std::string& origin) {
  const nlohmann::json doc = json::parse_text(text, origin);
  json::validate(doc, "tactile-sensors.schema.json", origin);
  SensorCatalog catalog;
  const auto& sensors = doc.at("sensors");
  for (std::size_t i = 0; i < sensors.size(); ++i) catalog.models_.push_back(model_from(sensors[i], origin, i));
  return catalog;
}

SensorCatalog SensorCatalog::builtin() {
  return parse(std::string(embedded::schema("tactile-sensors.json")), "schemas/tactile-sensors.json");
}

SensorCatalog SensorCatalog::from_file(const std::string& path) { return parse(json::read_file(path).dump(), path); }

void SensorCatalog::prepend(const SensorCatalog& other) {
  models_.insert(models_.begin(), other.models_.begin(), other.models_.end());
}

const SensorModel* SensorCatalog::match(std::uint16_t vendor_id, std::uint16_t product_id, const std::string& product) const {
  for (const auto& m : models_) {
    if (m.vendor_id != vendor_id || m.product_id != product_id) continue;
    if (!m.product_pattern.empty() && !std::regex_search(product, m.product_regex)) continue;
    return &m;
  }
  return nullptr;
}

std::string SensorCatalog::serial_of(const SensorModel& model, const std::string& product, const std::string& usb_serial) {
  std::smatch match;
  if (!model.serial_pattern.empty() && std::regex_search(product, match, model.serial_regex) && match[1].matched)
    return match[1].str();
  return usb_serial;
}

}  // namespace haptex::capture
