#pragma once
// USB devices as libusb enumerates them, with their strings. Reading strings through libusb needs
// write access to /dev/bus/usb; sysfs offers them to every user, so they are read there first.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace haptex::capture {

// The link a device negotiated with its port, as sysfs states it in the device's folder:
// `speed` in Mbit/s ("1.5", "12", "480", "5000", "10000", "20000") and `version`, the USB release
// the device declares (bcdUSB, " 2.00"). Either is unknown for the fake camera, without sysfs, or
// when its file is missing or garbled; nothing is judged from an unknown value.
struct UsbLink {
  std::optional<double> speed_mbps;
  std::optional<double> version;
  // "480 Mbit/s (USB 2.0 high speed)", or "speed unknown".
  std::string text() const;
  // The fastest speed the device's version allows when the link runs slower (a USB 2.0 device at
  // 12 Mbit/s behind a USB 1.1 hub, a USB 3 device on a USB 2.0 port or cable); nullopt otherwise.
  std::optional<double> faster_speed_possible() const;
};

// "USB 1.1 full speed", "USB 2.0 high speed", "USB 3 SuperSpeed (5 Gbit/s)", ... for sysfs's speeds;
// "" for a value sysfs does not use.
std::string usb_speed_name(double mbps);
// The link of /sys/bus/usb/devices/<usb_name> under sysfs_root.
UsbLink read_usb_link(const std::string& sysfs_root, const std::string& usb_name);

struct UsbDevice {
  std::uint16_t vendor_id = 0, product_id = 0;
  int bus = 0;
  std::vector<int> ports;  // the port path from the root hub
  std::string manufacturer, product, serial;
  // The device's name under /sys/bus/usb/devices: "1-2", "3-1.4.2".
  std::string sysfs_name() const;
};

// "0c45": a vendor or product ID as lsusb and the sensor list write it.
std::string usb_id_text(std::uint16_t id);

// Every device on every bus. Throws haptex::Error (failed) when libusb cannot start.
std::vector<UsbDevice> list_usb_devices(const std::string& sysfs_root = "/sys");

}  // namespace haptex::capture
