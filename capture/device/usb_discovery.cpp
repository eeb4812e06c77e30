#include "capture/device/usb_discovery.hpp"

#include <libusb-1.0/libusb.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "capture/device/sysfs_line.hpp"
#include "core/error.hpp"
#include "core/text/format.hpp"
#include "core/text/parse_number.hpp"

namespace haptex::capture {
namespace {

std::string descriptor_string(libusb_device_handle* handle, std::uint8_t index) {
  if (!handle || index == 0) return {};
  unsigned char text[256] = {};
  const int n = libusb_get_string_descriptor_ascii(handle, index, text, sizeof text);
  return n > 0 ? std::string(reinterpret_cast<char*>(text), std::size_t(n)) : std::string();
}

void fill_strings(libusb_device* device, const libusb_device_descriptor& d, const std::string& sysfs_root, UsbDevice& out) {
  const std::filesystem::path dir = std::filesystem::path(sysfs_root) / "bus/usb/devices" / out.sysfs_name();
  out.manufacturer = sysfs_line(dir / "manufacturer");
  out.product = sysfs_line(dir / "product");
  out.serial = sysfs_line(dir / "serial");
  if (!out.product.empty() || (d.iProduct == 0 && d.iSerialNumber == 0)) return;
  libusb_device_handle* handle = nullptr;
  if (libusb_open(device, &handle) != 0) return;  // no permission: the IDs still identify known sensors
  out.manufacturer = descriptor_string(handle, d.iManufacturer);
  out.product = descriptor_string(handle, d.iProduct);
  out.serial = descriptor_string(handle, d.iSerialNumber);
  libusb_close(handle);
}

// A positive number in a sysfs file, or nullopt: a missing file, or one holding anything else
// (wireless USB's "53.3-480", a truncated read) is unknown, never an error.
std::optional<double> read_positive(const std::filesystem::path& path) {
  const std::optional<double> value = text::parse_number(sysfs_line(path));
  if (!value || !std::isfinite(*value) || *value <= 0) return std::nullopt;
  return value;
}

std::string speed_text(double mbps) {
  return text::format("%g Mbit/s", mbps);
}

}  // namespace

std::string usb_id_text(std::uint16_t id) {
  return text::format("%04x", id);
}

std::string usb_speed_name(double mbps) {
  if (mbps == 1.5) return "USB 1.1 low speed";
  if (mbps == 12) return "USB 1.1 full speed";
  if (mbps == 480) return "USB 2.0 high speed";
  if (mbps == 5000) return "USB 3 SuperSpeed";
  if (mbps == 10000) return "USB 3 SuperSpeed+ 10 Gbit/s";
  if (mbps == 20000) return "USB 3 SuperSpeed+ 20 Gbit/s";
  return "";
}

std::string UsbLink::text() const {
  if (!speed_mbps) return "speed unknown";
  const std::string name = usb_speed_name(*speed_mbps);
  return speed_text(*speed_mbps) + (name.empty() ? "" : " (" + name + ")");
}

std::optional<double> UsbLink::faster_speed_possible() const {
  if (!speed_mbps || !version) return std::nullopt;
  // bcdUSB says which release the device follows; from 3.1 on it no longer tells Gen 1 from Gen 2,
  // so a USB 3 device is only known to reach 5 Gbit/s.
  const double fastest = *version >= 3.0 ? 5000.0 : *version >= 2.0 ? 480.0 : 12.0;
  return fastest > *speed_mbps ? std::optional<double>(fastest) : std::nullopt;
}

UsbLink read_usb_link(const std::string& sysfs_root, const std::string& usb_name) {
  const std::filesystem::path dir = std::filesystem::path(sysfs_root) / "bus/usb/devices" / usb_name;
  return {read_positive(dir / "speed"), read_positive(dir / "version")};
}

std::string UsbDevice::sysfs_name() const {
  std::string name = std::to_string(bus) + "-";
  for (std::size_t i = 0; i < ports.size(); ++i) name += (i ? "." : "") + std::to_string(ports[i]);
  return name;
}

std::vector<UsbDevice> list_usb_devices(const std::string& sysfs_root) {
  libusb_context* context = nullptr;
  if (const int error = libusb_init(&context); error != 0)
    throw failure(std::string("cannot list USB devices: libusb_init failed (") + libusb_error_name(error) + ")");
  const std::unique_ptr<libusb_context, decltype(&libusb_exit)> context_guard(context, libusb_exit);
  libusb_device** list = nullptr;
  const ssize_t count = libusb_get_device_list(context, &list);
  if (count < 0) throw failure(std::string("cannot list USB devices: ") + libusb_error_name(int(count)));
  std::vector<UsbDevice> out;
  for (ssize_t i = 0; i < count; ++i) {
    libusb_device_descriptor d{};
    if (libusb_get_device_descriptor(list[i], &d) != 0) continue;
    UsbDevice u;
    u.vendor_id = d.idVendor;
    u.product_id = d.idProduct;
    u.bus = libusb_get_bus_number(list[i]);
    std::uint8_t ports[8];
    const int depth = libusb_get_port_numbers(list[i], ports, sizeof ports);
    if (depth <= 0) continue;  // a root hub: not a sensor
    u.ports.assign(ports, ports + depth);
    fill_strings(list[i], d, sysfs_root, u);
    out.push_back(std::move(u));
  }
  libusb_free_device_list(list, 1);
  return out;
}

}  // namespace haptex::capture
