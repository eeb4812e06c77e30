#include "capture/device/camera_controls.hpp"

#include <linux/videodev2.h>

#include <cerrno>
#include <cstring>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <optional>

#include "core/error.hpp"
#include "core/text/format.hpp"

namespace haptex::capture {
namespace {

struct KnownControl {
  std::uint32_t id;
  const char* name;      // kernel 5.x and later (v4l2-ctl --list-ctrls)
  const char* old_name;  // earlier kernels; nullptr when unchanged
};

constexpr KnownControl kKnown[] = {
    {V4L2_CID_EXPOSURE_AUTO, "auto_exposure", "exposure_auto"},
    {V4L2_CID_EXPOSURE_ABSOLUTE, "exposure_time_absolute", "exposure_absolute"},
    {V4L2_CID_EXPOSURE_AUTO_PRIORITY, "exposure_dynamic_framerate", "exposure_auto_priority"},
    {V4L2_CID_EXPOSURE, "exposure", nullptr},
    {V4L2_CID_AUTO_WHITE_BALANCE, "white_balance_automatic", "white_balance_temperature_auto"},
    {V4L2_CID_WHITE_BALANCE_TEMPERATURE, "white_balance_temperature", nullptr},
    {V4L2_CID_AUTOGAIN, "gain_automatic", "autogain"},
    {V4L2_CID_GAIN, "gain", nullptr},
    {V4L2_CID_BRIGHTNESS, "brightness", nullptr},
    {V4L2_CID_CONTRAST, "contrast", nullptr},
    {V4L2_CID_SATURATION, "saturation", nullptr},
    {V4L2_CID_SHARPNESS, "sharpness", nullptr},
    {V4L2_CID_BACKLIGHT_COMPENSATION, "backlight_compensation", nullptr},
    {V4L2_CID_POWER_LINE_FREQUENCY, "power_line_frequency", nullptr},
};

// One automatic loop: the switch that turns it off, and the value(s) it would otherwise move.
struct LockGroup {
  const char* what;
  std::uint32_t auto_id;
  std::int64_t manual_value;  // the auto control's "off" value
  std::vector<std::uint32_t> value_ids;  // the first the device has is pinned
};

const std::vector<LockGroup>& lock_groups() {
  static const std::vector<LockGroup> groups = {
      {"exposure", V4L2_CID_EXPOSURE_AUTO, V4L2_EXPOSURE_MANUAL, {V4L2_CID_EXPOSURE_ABSOLUTE, V4L2_CID_EXPOSURE}},
      // With auto priority on, UVC cameras lengthen exposure by dropping the frame rate.
      {"exposure priority", V4L2_CID_EXPOSURE_AUTO_PRIORITY, 0, {}},
      {"white balance", V4L2_CID_AUTO_WHITE_BALANCE, 0, {V4L2_CID_WHITE_BALANCE_TEMPERATURE}},
      {"gain", V4L2_CID_AUTOGAIN, 0, {V4L2_CID_GAIN}},
  };
  return groups;
}

std::string hex(std::uint32_t id) {
  return text::format("0x%08x", id);
}

std::optional<v4l2_queryctrl> query(const V4l2Device& device, std::uint32_t id) {
  v4l2_queryctrl q{};
  q.id = id;
  if (device.try_ioctl(VIDIOC_QUERYCTRL, &q) != 0 || (q.flags & V4L2_CTRL_FLAG_DISABLED)) return std::nullopt;
  return q;
}

std::int64_t get_value(const V4l2Device& device, std::uint32_t id) {
  v4l2_control c{};
  c.id = id;
  device.ioctl_or_throw(VIDIOC_G_CTRL, &c, "reading control " + control_name(id));
  return c.value;
}

void set_value(const V4l2Device& device, const v4l2_queryctrl& q, std::int64_t value, bool requested) {
  if (requested && (value < q.minimum || value > q.maximum))
    throw input_error(device.path(), "control " + control_name(q.id),
                      std::to_string(value) + " is outside the control's range " + std::to_string(q.minimum) + ".." +
                          std::to_string(q.maximum),
                      "Give a value in that range with --control");
  v4l2_control c{};
  c.id = q.id;
  c.value = static_cast<std::int32_t>(value);
  const int error = device.try_ioctl(VIDIOC_S_CTRL, &c);
  if (error != 0)
    throw failure(device.path() + ": setting control " + control_name(q.id) + " to " + std::to_string(value) +
                  " failed: " + std::strerror(error));
}

void lock_group(const V4l2Device& device, const LockGroup& group, std::map<std::uint32_t, std::int64_t>& values,
                ControlLock& out) {
  // Read the value first: it is what the automatic loop settled on for this scene.
  std::optional<v4l2_queryctrl> value_control;
  for (std::uint32_t id : group.value_ids)
    if ((value_control = query(device, id))) break;
  std::optional<std::int64_t> settled;
  if (value_control) settled = get_value(device, value_control->id);

  if (const auto auto_control = query(device, group.auto_id)) {
    set_value(device, *auto_control, group.manual_value, false);
    out.locked.push_back({control_name(group.auto_id), group.auto_id, get_value(device, group.auto_id), false});
  } else {
    out.missing.push_back(control_name(group.auto_id));
  }
  if (group.value_ids.empty()) return;
  if (!value_control) {
    out.missing.push_back(control_name(group.value_ids.front()));
    return;
  }
  const auto given = values.find(value_control->id);
  const bool requested = given != values.end();
  set_value(device, *value_control, requested ? given->second : *settled, requested);
  if (requested) values.erase(given);
  out.locked.push_back({control_name(value_control->id), value_control->id, get_value(device, value_control->id), requested});
}

}  // namespace

std::uint32_t control_id(std::string_view name) {
  for (const auto& k : kKnown)
    if (name == k.name || (k.old_name && name == k.old_name)) return k.id;
  if (!name.empty() && std::isdigit(static_cast<unsigned char>(name.front()))) {
    char* end = nullptr;
    const std::string text(name);
    const unsigned long id = std::strtoul(text.c_str(), &end, 0);
    if (end && *end == '\0' && id <= 0xffffffffUL) return static_cast<std::uint32_t>(id);
  }
  std::string known;
  for (const auto& k : kKnown) known += (known.empty() ? "" : ", ") + std::string(k.name);
  throw input_error("--control", std::string(name), "unknown control name",
                    "Use a V4L2 control name (" + known + ", or their pre-5.x names) or a numeric control ID");
}

std::string control_name(std::uint32_t id) {
  for (const auto& k : kKnown)
    if (k.id == id) return k.name;
  return hex(id);
}

ControlLock lock_controls(const V4l2Device& device, const std::map<std::uint32_t, std::int64_t>& values) {
  std::map<std::uint32_t, std::int64_t> remaining = values;
  ControlLock out;
  for (const auto& group : lock_groups()) lock_group(device, group, remaining, out);
  for (const auto& [id, value] : remaining) {  // controls outside the automatic loops
    const auto q = query(device, id);
    if (!q)
      throw input_error(device.path(), "control " + control_name(id), "the device has no such control",
                        "List its controls with 'v4l2-ctl -d " + device.path() + " --list-ctrls'");
    set_value(device, *q, value, true);
    out.locked.push_back({control_name(id), id, get_value(device, id), true});
  }
  return out;
}

}  // namespace haptex::capture
