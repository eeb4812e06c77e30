#pragma once
// Known tactile sensors among the USB devices, each with its serial and its /dev/videoN nodes,
// found through sysfs: a UVC interface's video4linux/ folder lists the nodes the driver made, and
// their `index` tells the capture node (0) from the metadata node (1).
#include <string>
#include <vector>

#include "capture/device/sensor_catalog.hpp"
#include "capture/device/usb_discovery.hpp"

namespace haptex::capture {

struct VideoNode {
  std::string name;      // video0
  std::string dev_path;  // /dev/video0
  std::string label;     // the node's name in sysfs ("GelSight Mini R0B 2BNK-CE6G: Ge")
  int index = 0;         // the node's number within its interface
  bool capture = false;  // the node to record from
};

struct DiscoveredSensor {
  std::string model, serial;
  UsbDevice usb;
  std::vector<VideoNode> nodes;
  std::string capture_node;  // empty when the driver made no node (not bound yet, or not UVC)
};

std::vector<VideoNode> video_nodes(const std::string& sysfs_root, const std::string& usb_sysfs_name);
std::vector<DiscoveredSensor> discover_sensors(const std::vector<UsbDevice>& devices, const SensorCatalog& catalog,
                                               const std::string& sysfs_root = "/sys");
// The one connected sensor with this serial. Throws haptex::Error (bad_input) naming the serials
// found when there is none, and when it has no capture node.
DiscoveredSensor find_sensor_by_serial(const std::vector<DiscoveredSensor>& sensors, const std::string& serial);

}  // namespace haptex::capture
