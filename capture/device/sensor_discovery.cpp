#include "capture/device/sensor_discovery.hpp"

#include <algorithm>
#include <filesystem>
#include <functional>

#include "capture/device/sysfs_line.hpp"
#include "core/error.hpp"

namespace haptex::capture {
namespace fs = std::filesystem;
namespace {

int read_int(const fs::path& path, int fallback) {
  try {
    return std::stoi(sysfs_line(path));
  } catch (...) {
    return fallback;
  }
}

// Every /sys/bus/usb/devices/<interface>/video4linux/videoN folder, with the interface's name.
// Interfaces are named "<device>:<configuration>.<interface>", e.g. "1-2:1.0".
void for_each_video_node(const std::string& sysfs_root,
                         const std::function<void(const std::string& interface, const fs::path& node)>& visit) {
  const fs::path devices = fs::path(sysfs_root) / "bus/usb/devices";
  std::error_code ec;
  if (!fs::is_directory(devices, ec)) return;
  for (const auto& interface : fs::directory_iterator(devices, ec)) {
    const std::string name = interface.path().filename().string();
    if (name.find(':') == std::string::npos) continue;
    const fs::path v4l = interface.path() / "video4linux";
    if (!fs::is_directory(v4l, ec)) continue;
    for (const auto& node : fs::directory_iterator(v4l, ec))
      if (node.path().filename().string().rfind("video", 0) == 0) visit(name, node.path());
  }
}

}  // namespace

std::vector<VideoNode> video_nodes(const std::string& sysfs_root, const std::string& usb_name) {
  std::vector<VideoNode> nodes;
  for_each_video_node(sysfs_root, [&](const std::string& interface, const fs::path& node) {
    if (interface.rfind(usb_name + ":", 0) != 0) return;
    const std::string node_name = node.filename().string();
    nodes.push_back({node_name, "/dev/" + node_name, sysfs_line(node / "name"), read_int(node / "index", 0), false});
  });
  std::sort(nodes.begin(), nodes.end(), [](const VideoNode& a, const VideoNode& b) {
    return a.index != b.index ? a.index < b.index : a.name < b.name;
  });
  if (!nodes.empty()) nodes.front().capture = true;  // UVC: index 0 captures, index 1 carries metadata
  return nodes;
}

UsbLink usb_link_of_node(const std::string& sysfs_root, const std::string& node) {
  // /dev/v4l/by-id/... names are links to /dev/videoN; sysfs knows the node by that name.
  std::error_code ec;
  const fs::path resolved = fs::canonical(node, ec);
  const std::string name = (ec ? fs::path(node) : resolved).filename().string();
  std::string device;
  for_each_video_node(sysfs_root, [&](const std::string& interface, const fs::path& found) {
    if (found.filename() == name) device = interface.substr(0, interface.find(':'));
  });
  return device.empty() ? UsbLink{} : read_usb_link(sysfs_root, device);
}

std::vector<DiscoveredSensor> discover_sensors(const std::vector<UsbDevice>& devices, const SensorCatalog& catalog,
                                               const std::string& sysfs_root) {
  std::vector<DiscoveredSensor> out;
  for (const auto& usb : devices) {
    const SensorModel* model = catalog.match(usb.vendor_id, usb.product_id, usb.product);
    if (!model) continue;
    DiscoveredSensor s;
    s.model = model->model;
    s.serial = SensorCatalog::serial_of(*model, usb.product, usb.serial);
    s.usb = usb;
    s.nodes = video_nodes(sysfs_root, usb.sysfs_name());
    s.link = read_usb_link(sysfs_root, usb.sysfs_name());
    for (const auto& n : s.nodes)
      if (n.capture) s.capture_node = n.dev_path;
    out.push_back(std::move(s));
  }
  std::sort(out.begin(), out.end(), [](const DiscoveredSensor& a, const DiscoveredSensor& b) {
    return a.usb.sysfs_name() < b.usb.sysfs_name();
  });
  return out;
}

std::string describe(const DiscoveredSensor& s) {
  std::string line = s.model + "  serial " + (s.serial.empty() ? "(none)" : s.serial) + "  USB " + s.usb.sysfs_name() +
                     " (" + usb_id_text(s.usb.vendor_id) + ":" + usb_id_text(s.usb.product_id) + ") " + s.link.text();
  if (const auto faster = s.link.faster_speed_possible())
    line += " [the device supports " + usb_speed_name(*faster) + ": try another port]";
  if (s.capture_node.empty()) line += "  no video node (driver not bound?)";
  for (const auto& n : s.nodes) line += std::string("  ") + (n.capture ? "capture " : "metadata ") + n.dev_path;
  return line;
}

DiscoveredSensor find_sensor_by_serial(const std::vector<DiscoveredSensor>& sensors, const std::string& serial) {
  std::string found;
  for (const auto& s : sensors) {
    if (s.serial == serial) {
      if (s.capture_node.empty())
        throw input_error("--serial " + serial, "", s.model + " found on USB " + s.usb.sysfs_name() + " but it has no video node",
                          "Replug the sensor; 'ls /sys/bus/usb/devices/" + s.usb.sysfs_name() + "*/video4linux' should list one");
      return s;
    }
    found += (found.empty() ? "" : ", ") + s.model + " " + (s.serial.empty() ? "(no serial)" : s.serial);
  }
  throw input_error("--serial " + serial, "", "no connected tactile sensor has this serial (found: " +
                                                  (found.empty() ? std::string("none") : found) + ")",
                    "List the sensors with 'haptex capture devices', or give the node with --device");
}

}  // namespace haptex::capture
