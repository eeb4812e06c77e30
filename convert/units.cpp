#include "convert/units.hpp"

#include <map>
#include <utility>
#include <vector>

namespace haptex::convert {
namespace {

using Scales = std::vector<std::pair<std::string, double>>;

const std::map<std::string, Scales>& table() {
  static const std::map<std::string, Scales> scales = {
      {"accel", {{"m/s^2", 1.0}, {"m/s2", 1.0}, {"g", 9.80665}}},
      {"force", {{"N", 1.0}, {"mN", 1e-3}}},
      {"speed", {{"mm/s", 1.0}, {"m/s", 1e3}, {"cm/s", 10.0}}},
      {"position", {{"mm", 1.0}, {"m", 1e3}, {"cm", 10.0}}},
  };
  return scales;
}

}  // namespace

std::optional<double> unit_scale(const std::string& quantity, const std::string& unit) {
  auto it = table().find(quantity);
  if (it == table().end()) return std::nullopt;
  for (const auto& [name, scale] : it->second)
    if (name == unit) return scale;
  return std::nullopt;
}

std::string accepted_units(const std::string& quantity) {
  std::string list;
  auto it = table().find(quantity);
  if (it == table().end()) return list;
  for (const auto& entry : it->second) list += (list.empty() ? "" : ", ") + entry.first;
  return list;
}

}  // namespace haptex::convert
