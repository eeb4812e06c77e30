#include "capture/device/usb_discovery.hpp"

#include <libusb-1.0/libusb.h>

#include <filesystem>
#include <fstream>
#include <memory>

#include "core/error.hpp"

namespace haptex::capture {
namespace {

std::string read_line(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  return line;
}

std::string descriptor_string(libusb_device_handle* handle, std::uint8_t index) {
  if (!handle || index == 0) return {};
  unsigned char text[256] = {};
  const int n = libusb_get_string_descriptor_ascii(handle, index, text, sizeof text);
  return n > 0 ? std::string(reinterpret_cast<char*>(text), std::size_t(n)) : std::string();
}

void fill_strings(libusb_device* device, const libusb_device_descriptor& d, const std::string& sysfs_root, UsbDevice& out) {
  const std::filesystem::path dir = std::filesystem::path(sysfs_root) / "bus/usb/devices" / out.sysfs_name();
  out.manufacturer = read_line(dir / "manufacturer");
  out.product = read_line(dir / "product");
  out.serial = read_line(dir / "serial");
  if (!out.product.empty() || (d.iProduct == 0 && d.iSerialNumber == 0)) return;
  libusb_device_handle* handle = nullptr;
  if (libusb_open(device, &handle) != 0) return;  // no permission: the IDs still identify known sensors
  out.manufacturer = descriptor_string(handle, d.iManufacturer);
  out.product = descriptor_string(handle, d.iProduct);
  out.serial = descriptor_string(handle, d.iSerialNumber);
  libusb_close(handle);
}

}  // namespace

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
