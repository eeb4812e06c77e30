#include "capture/device/sensor_discovery.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "core/error.hpp"

namespace haptex::capture {
namespace fs = std::filesystem;
namespace {

std::string read_line(const fs::path& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  return line;
}

int read_int(const fs::path& path, int fallback) {
  try {
    return std::stoi(read_line(path));
  } catch (...) {
    return fallback;
  }
}

}  // namespace

std::vector<VideoNode> video_nodes(const std::string& sysfs_root, const std::string& usb_name) {
  const fs::path devices = fs::path(sysfs_root) / "bus/usb/devices";
  std::vector<VideoNode> nodes;
  std::error_code ec;
  if (!fs::is_directory(devices, ec)) return nodes;
  // Interfaces are named "<device>:<configuration>.<interface>", e.g. "1-2:1.0".
  for (const auto& interface : fs::directory_iterator(devices, ec)) {
    const std::string name = interface.path().filename().string();
    if (name.rfind(usb_name + ":", 0) != 0) continue;
    const fs::path v4l = interface.path() / "video4linux";
    if (!fs::is_directory(v4l, ec)) continue;
    for (const auto& node : fs::directory_iterator(v4l, ec)) {
      const std::string node_name = node.path().filename().string();
      if (node_name.rfind("video", 0) != 0) continue;
      nodes.push_back({node_name, "/dev/" + node_name, read_line(node.path() / "name"), read_int(node.path() / "index", 0), false});
    }
  }
  std::sort(nodes.begin(), nodes.end(), [](const VideoNode& a, const VideoNode& b) {
    return a.index != b.index ? a.index < b.index : a.name < b.name;
  });
  if (!nodes.empty()) nodes.front().capture = true;  // UVC: index 0 captures, index 1 carries metadata
  return nodes;
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
    for (const auto& n : s.nodes)
      if (n.capture) s.capture_node = n.dev_path;
    out.push_back(std::move(s));
  }
  std::sort(out.begin(), out.end(), [](const DiscoveredSensor& a, const DiscoveredSensor& b) {
    return a.usb.sysfs_name() < b.usb.sysfs_name();
  });
  return out;
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
