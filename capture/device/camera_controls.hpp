#pragma once
// Exposure, white balance and gain locked for the whole take: the automatic loops would shift the
// no-contact baseline while the user presses, and every press would look different. Controls are
// handled by V4L2 control ID; users may name them by the current kernel names (auto_exposure,
// exposure_time_absolute, white_balance_automatic, ...) or the pre-5.x ones (exposure_auto,
// exposure_absolute, white_balance_temperature_auto, ...).
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "capture/device/v4l2_device.hpp"

namespace haptex::capture {

// The control ID for a name (either generation) or a number ("0x009a0902", "10094850").
// Throws haptex::Error (bad_input) listing the known names when it is neither.
std::uint32_t control_id(std::string_view name);
// The current kernel name of a known control ID; "0x........" for others.
std::string control_name(std::uint32_t id);

struct LockedControl {
  std::string name;
  std::uint32_t id = 0;
  std::int64_t value = 0;
  bool requested = false;  // the user gave the value; otherwise it is the value the device was using
};

struct ControlLock {
  std::vector<LockedControl> locked;  // automatic modes switched off, then the manual values
  std::vector<std::string> missing;   // controls this device does not have
};

// Switches automatic exposure, white balance and gain off and pins their values: `values` (by control
// ID) where given, else what the automatic loop had settled on. Values for other controls in `values`
// are set as given. Throws haptex::Error (bad_input) when a given value is out of the control's range
// or names a control the device lacks, (failed) when the device refuses a setting.
ControlLock lock_controls(const V4l2Device& device, const std::map<std::uint32_t, std::int64_t>& values);

}  // namespace haptex::capture
