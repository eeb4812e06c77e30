#pragma once
// USB devices as libusb enumerates them, with their strings. Reading strings through libusb needs
// write access to /dev/bus/usb; sysfs offers them to every user, so they are read there first.
#include <cstdint>
#include <string>
#include <vector>

namespace haptex::capture {

struct UsbDevice {
  std::uint16_t vendor_id = 0, product_id = 0;
  int bus = 0;
  std::vector<int> ports;  // the port path from the root hub
  std::string manufacturer, product, serial;
  // The device's name under /sys/bus/usb/devices: "1-2", "3-1.4.2".
  std::string sysfs_name() const;
};

// Every device on every bus. Throws haptex::Error (failed) when libusb cannot start.
std::vector<UsbDevice> list_usb_devices(const std::string& sysfs_root = "/sys");

}  // namespace haptex::capture
