#pragma once
// The units haptex stores (docs/architecture.md, "Signals and conventions") and the few others it converts from.
#include <optional>
#include <string>

namespace haptex::convert {

// Factor that turns a value in `unit` into haptex's unit for `quantity` ("accel", "force",
// "speed", "position"); nullopt when the unit is unknown for that quantity.
std::optional<double> unit_scale(const std::string& quantity, const std::string& unit);
// The accepted spellings, for error messages: "m/s^2, g".
std::string accepted_units(const std::string& quantity);

}  // namespace haptex::convert
