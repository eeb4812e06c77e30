// haptex capture devices [--json] [--sensors FILE]: the tactile sensors on USB, their link speeds and
// their video nodes.
#include <iostream>
#include <nlohmann/json.hpp>

#include "apps/capture_subcommands.hpp"
#include "capture/device/sensor_discovery.hpp"

namespace haptex::apps {
namespace {

nlohmann::json optional_number(const std::optional<double>& value) { return value ? nlohmann::json(*value) : nlohmann::json(); }

class CaptureDevices : public CaptureSubcommand {
 public:
  CLI::App* declare(CLI::App& capture) override {
    CLI::App* app = capture.add_subcommand("devices", "List connected tactile sensors (USB) and their capture nodes");
    app->add_option("--sensors", sensors_, "JSON list of more sensors (the form of schemas/tactile-sensors.json)");
    return app;
  }

  int run(const GlobalOptions& global) override {
    capture::SensorCatalog catalog = capture::SensorCatalog::builtin();
    if (!sensors_.empty()) catalog.prepend(capture::SensorCatalog::from_file(sensors_));
    const auto usb = capture::list_usb_devices();
    const auto sensors = capture::discover_sensors(usb, catalog);
    if (global.json) {
      std::cout << to_json(sensors, usb.size()).dump(2) << "\n";
      return 0;
    }
    if (sensors.empty()) {
      std::string known;
      for (const auto& m : catalog.models())
        known += (known.empty() ? "" : ", ") + m.model + " (" + capture::usb_id_text(m.vendor_id) + ":" + capture::usb_id_text(m.product_id) + ")";
      std::cout << "no tactile sensor found among " << usb.size() << " USB devices. Known sensors: " << known
                << ". Add others with --sensors FILE.\n";
      return 0;
    }
    for (const auto& s : sensors) std::cout << capture::describe(s) << "\n";
    return 0;
  }

 private:
  static nlohmann::json to_json(const std::vector<capture::DiscoveredSensor>& sensors, std::size_t checked) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& s : sensors) {
      nlohmann::json nodes = nlohmann::json::array();
      for (const auto& n : s.nodes)
        nodes.push_back({{"node", n.dev_path}, {"name", n.label}, {"index", n.index}, {"capture", n.capture}});
      list.push_back({{"model", s.model}, {"serial", s.serial}, {"vendor_id", capture::usb_id_text(s.usb.vendor_id)},
                      {"product_id", capture::usb_id_text(s.usb.product_id)}, {"usb_path", s.usb.sysfs_name()},
                      {"product", s.usb.product}, {"manufacturer", s.usb.manufacturer},
                      {"usb_speed_mbps", optional_number(s.link.speed_mbps)},
                      {"usb_version", optional_number(s.link.version)},
                      {"capture_node", s.capture_node}, {"nodes", nodes}});
    }
    return {{"sensors", list}, {"usb_devices_checked", checked}};
  }

  std::string sensors_;
};

}  // namespace

std::unique_ptr<CaptureSubcommand> make_capture_devices() { return std::make_unique<CaptureDevices>(); }

}  // namespace haptex::apps
