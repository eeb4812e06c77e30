#pragma once
// Known tactile sensors among the USB devices, each with its serial, its /dev/videoN nodes and its
// USB link speed, found through sysfs: a UVC interface's video4linux/ folder lists the nodes the
// driver made, and their `index` tells the capture node (0) from the metadata node (1); the device's
// folder holds the `speed` its link negotiated.
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
  UsbLink link;              // the USB link's speed, from sysfs
};

std::vector<VideoNode> video_nodes(const std::string& sysfs_root, const std::string& usb_sysfs_name);
// The USB link of the device a video node (/dev/videoN, or a link to one) belongs to; unknown when
// sysfs does not list the node under a USB interface.
UsbLink usb_link_of_node(const std::string& sysfs_root, const std::string& node);
std::vector<DiscoveredSensor> discover_sensors(const std::vector<UsbDevice>& devices, const SensorCatalog& catalog,
                                               const std::string& sysfs_root = "/sys");
// The sensor as `haptex capture devices` lists it: model, serial, USB path and IDs, link speed (and a
// hint when the device supports a faster link than it got), video nodes.
std::string describe(const DiscoveredSensor& sensor);
// The one connected sensor with this serial. Throws haptex::Error (bad_input) naming the serials
// found when there is none, and when it has no capture node.
DiscoveredSensor find_sensor_by_serial(const std::vector<DiscoveredSensor>& sensors, const std::string& serial);

}  // namespace haptex::capture
