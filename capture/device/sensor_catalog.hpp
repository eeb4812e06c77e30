#pragma once
// The USB tactile sensors haptex recognises (schemas/tactile-sensors.json, compiled in), extended by
// a user's own file of the same form (--sensors): vendor and product IDs, and where IDs are generic
// (the GelSight Mini uses a stock Microdia webcam ID) a pattern the product string must match.
#include <cstdint>
#include <regex>
#include <string>
#include <vector>

namespace haptex::capture {

struct SensorModel {
  std::string model;
  std::uint16_t vendor_id = 0, product_id = 0;
  std::string product_pattern, serial_pattern;  // ECMAScript regular expressions, may be empty
  std::string notes;
  std::regex product_regex, serial_regex;
};

class SensorCatalog {
 public:
  static SensorCatalog builtin();
  // Validates against schemas/tactile-sensors.schema.json; throws haptex::Error (bad_input) naming
  // the file and entry otherwise.
  static SensorCatalog from_file(const std::string& path);
  // The other catalog's entries are tried first.
  void prepend(const SensorCatalog& other);

  const SensorModel* match(std::uint16_t vendor_id, std::uint16_t product_id, const std::string& product) const;
  // The serial of a matched device: found in the product string when the model says so, else the USB serial.
  static std::string serial_of(const SensorModel& model, const std::string& product, const std::string& usb_serial);
  const std::vector<SensorModel>& models() const { return models_; }

 private:
  static SensorCatalog parse(const std::string& text, const std::string& origin);
  std::vector<SensorModel> models_;
};

}  // namespace haptex::capture
