// USB discovery against a fake sysfs tree, as libusb would list the devices.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "capture/device/sensor_discovery.hpp"
#include "core/error.hpp"
#include "core/text/format.hpp"
#include "dataset/press_file.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::capture {
namespace {

namespace fs = std::filesystem;

// /sys/bus/usb/devices/<usb>:1.0/video4linux/videoN/{name,index}, as uvcvideo makes them.
void add_node(const fs::path& sysfs, const std::string& usb, const std::string& node, int index, const std::string& name) {
  const fs::path dir = sysfs / "bus/usb/devices" / (usb + ":1.0") / "video4linux" / node;
  fs::create_directories(dir);
  std::ofstream(dir / "name") << name << "\n";
  std::ofstream(dir / "index") << index << "\n";
}

// /sys/bus/usb/devices/<usb>/<file>: the device's own attributes (speed, version).
void write_usb_file(const fs::path& sysfs, const std::string& usb, const std::string& file, const std::string& text) {
  const fs::path dir = sysfs / "bus/usb/devices" / usb;
  fs::create_directories(dir);
  std::ofstream(dir / file) << text;
}

UsbDevice usb(std::uint16_t vendor, std::uint16_t product, int bus, std::vector<int> ports, std::string name,
              std::string serial = {}) {
  UsbDevice d;
  d.vendor_id = vendor;
  d.product_id = product;
  d.bus = bus;
  d.ports = std::move(ports);
  d.product = std::move(name);
  d.serial = std::move(serial);
  return d;
}

class Discovery : public ::testing::Test {
 protected:
  void SetUp() override {
    add_node(sysfs(), "1-2", "video2", 0, "GelSight Mini R0B 2BNK-CE6G: Ge");
    add_node(sysfs(), "1-2", "video3", 1, "GelSight Mini R0B 2BNK-CE6G: Ge");
    add_node(sysfs(), "3-1.4", "video0", 0, "DIGIT: DIGIT");
    add_node(sysfs(), "1-5", "video4", 0, "Integrated Webcam");
  }
  fs::path sysfs() const { return dir_.path() / "sys"; }
  std::vector<UsbDevice> devices() const {
    return {usb(0x0c45, 0x636d, 1, {2}, "GelSight Mini R0B 2BNK-CE6G"),
            usb(0x2833, 0x0209, 3, {1, 4}, "DIGIT", "D20345"),
            usb(0x0c45, 0x636d, 1, {5}, "Integrated Webcam"),  // the same generic ID: not a GelSight
            usb(0x046d, 0xc52b, 1, {3}, "USB Receiver")};
  }
  haptex::test::TempDir dir_;
};

TEST_F(Discovery, FindsKnownSensorsTheirSerialsAndCaptureNodes) {
  const auto sensors = discover_sensors(devices(), SensorCatalog::builtin(), sysfs().string());
  ASSERT_EQ(sensors.size(), 2u);
  EXPECT_EQ(sensors[0].model, "GelSight Mini");
  EXPECT_EQ(sensors[0].serial, "2BNK-CE6G") << "from inside the product string";
  EXPECT_EQ(sensors[0].capture_node, "/dev/video2");
  ASSERT_EQ(sensors[0].nodes.size(), 2u);
  EXPECT_FALSE(sensors[0].nodes[1].capture) << "video3 is the metadata node";
  EXPECT_EQ(sensors[1].model, "DIGIT");
  EXPECT_EQ(sensors[1].serial, "D20345") << "the USB serial number";
  EXPECT_EQ(sensors[1].usb.sysfs_name(), "3-1.4");
  EXPECT_EQ(sensors[1].capture_node, "/dev/video0");
}

TEST_F(Discovery, ASensorWithoutANodeIsListedWithoutOne) {
  const auto sensors = discover_sensors({usb(0x2833, 0x0209, 2, {7}, "DIGIT", "D1")}, SensorCatalog::builtin(),
                                        sysfs().string());
  ASSERT_EQ(sensors.size(), 1u);
  EXPECT_TRUE(sensors[0].capture_node.empty());
  try {
    find_sensor_by_serial(sensors, "D1");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("has no video node"), std::string::npos) << e.what();
  }
}

TEST_F(Discovery, FindsASensorBySerialOrSaysWhichThereAre) {
  const auto sensors = discover_sensors(devices(), SensorCatalog::builtin(), sysfs().string());
  EXPECT_EQ(find_sensor_by_serial(sensors, "D20345").capture_node, "/dev/video0");
  try {
    find_sensor_by_serial(sensors, "XXXX");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::bad_input);
    EXPECT_NE(std::string(e.what()).find("found: GelSight Mini 2BNK-CE6G, DIGIT D20345"), std::string::npos) << e.what();
  }
}

TEST_F(Discovery, UsersAddTheirOwnSensors) {
  std::ofstream(dir_.file("mine.json")) << R"({"format": "tactile-sensors/1", "sensors": [
      {"model": "Lab webcam GelSight", "vendor_id": "0c45", "product_id": "636d", "product_pattern": "^Integrated"}]})";
  SensorCatalog catalog = SensorCatalog::builtin();
  catalog.prepend(SensorCatalog::from_file(dir_.file("mine.json")));
  const auto sensors = discover_sensors(devices(), catalog, sysfs().string());
  ASSERT_EQ(sensors.size(), 3u);
  EXPECT_EQ(sensors[1].model, "Lab webcam GelSight");
  EXPECT_EQ(sensors[1].capture_node, "/dev/video4");
}

TEST_F(Discovery, RefusesABadSensorList) {
  std::ofstream(dir_.file("bad.json")) << R"({"format": "tactile-sensors/1", "sensors": [{"model": "X", "vendor_id": "0C45", "product_id": "636d"}]})";
  try {
    SensorCatalog::from_file(dir_.file("bad.json"));
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::bad_input);
    EXPECT_NE(std::string(e.what()).find("bad.json: /sensors/0/vendor_id"), std::string::npos) << e.what();
  }
  std::ofstream(dir_.file("regex.json")) << R"({"format": "tactile-sensors/1", "sensors": [{"model": "X", "vendor_id": "0c45", "product_id": "636d", "product_pattern": "(["}]})";
  try {
    SensorCatalog::from_file(dir_.file("regex.json"));
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/sensors/0/product_pattern"), std::string::npos) << e.what();
  }
}

// Review 23, F6: libstdc++ compiles a regular expression by recursion, so a pattern nested 30 000 deep
// (60 KB of valid JSON) overflowed the stack: SIGSEGV in `capture devices`. Patterns are bounded by the
// schema, before std::regex sees them.
TEST_F(Discovery, ARegularExpressionTooLongToCompileIsRefusedByItsPlace) {
  for (const char* field : {"product_pattern", "serial_pattern"}) {
    const std::string deep = std::string(30000, '(') + "a" + std::string(30000, ')');
    std::ofstream(dir_.file("deep.json")) << R"({"format": "tactile-sensors/1", "sensors": [{"model": "X", "vendor_id": "0c45", "product_id": "636d", ")"
                                          << field << R"(": ")" << deep << R"("}]})";
    try {
      SensorCatalog::from_file(dir_.file("deep.json"));
      FAIL() << field;
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), Error::Kind::bad_input);
      EXPECT_NE(std::string(e.what()).find(std::string("/sensors/0/") + field), std::string::npos) << e.what();
    }
  }
}

// Review 8, #9: a mode of 1e39 frames a second was taken. The schema's bounds are the press file's
// (dataset/press_file.hpp), so a rate the list allows is one a press file can state.
TEST_F(Discovery, ASensorModeHasARateAPressFileCanState) {
  const auto list_with = [&](const std::string& mode) {
    std::ofstream(dir_.file("modes.json")) << R"({"format": "tactile-sensors/1", "sensors": [{"model": "X", "vendor_id": "0c45", "product_id": "636d", "modes": [)" +
                                                   mode + "]}]}";
    return dir_.file("modes.json");
  };
  EXPECT_NO_THROW(SensorCatalog::from_file(list_with(text::format(R"({"width": 65535, "height": 1, "fps": %g})", dataset::kHighestFps))));
  EXPECT_NO_THROW(SensorCatalog::from_file(list_with(text::format(R"({"width": 1, "height": 1, "fps": %g})", dataset::kLowestFps))));
  for (const std::string& bad : {text::format(R"({"width": 640, "height": 480, "fps": %.17g})", std::nextafter(dataset::kHighestFps, 1e9)),
                                text::format(R"({"width": 640, "height": 480, "fps": %.17g})", std::nextafter(dataset::kLowestFps, 0.0)),
                                std::string(R"({"width": 640, "height": 480, "fps": 1e39})"),
                                std::string(R"({"width": 65536, "height": 480, "fps": 30})")}) {
    try {
      SensorCatalog::from_file(list_with(bad));
      ADD_FAILURE() << bad << " was taken";
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), Error::Kind::bad_input);
      EXPECT_NE(std::string(e.what()).find("/sensors/0/modes/0/"), std::string::npos) << e.what();
    }
  }
}

TEST_F(Discovery, ReportsEachSensorsUsbLinkSpeed) {
  write_usb_file(sysfs(), "1-2", "speed", "480\n");
  write_usb_file(sysfs(), "1-2", "version", " 2.00\n");
  write_usb_file(sysfs(), "3-1.4", "speed", "12\n");  // a USB 2.0 device behind a USB 1.1 hub
  write_usb_file(sysfs(), "3-1.4", "version", " 2.00\n");
  const auto sensors = discover_sensors(devices(), SensorCatalog::builtin(), sysfs().string());
  ASSERT_EQ(sensors.size(), 2u);
  EXPECT_EQ(sensors[0].link.speed_mbps, 480.0);
  EXPECT_EQ(sensors[0].link.version, 2.0);
  EXPECT_EQ(sensors[0].link.text(), "480 Mbit/s (USB 2.0 high speed)");
  EXPECT_FALSE(sensors[0].link.faster_speed_possible()) << "a USB 2.0 device at 480 Mbit/s is as fast as it goes";
  EXPECT_EQ(sensors[1].link.text(), "12 Mbit/s (USB 1.1 full speed)");
  EXPECT_EQ(sensors[1].link.faster_speed_possible(), 480.0);
  // As `haptex capture devices` lists them.
  EXPECT_EQ(describe(sensors[0]), "GelSight Mini  serial 2BNK-CE6G  USB 1-2 (0c45:636d) 480 Mbit/s (USB 2.0 high speed)"
                                  "  capture /dev/video2  metadata /dev/video3");
  EXPECT_EQ(describe(sensors[1]), "DIGIT  serial D20345  USB 3-1.4 (2833:0209) 12 Mbit/s (USB 1.1 full speed)"
                                  " [the device supports USB 2.0 high speed: try another port]  capture /dev/video0");
}

TEST_F(Discovery, AMissingOrGarbledSpeedIsUnknownAndBreaksNothing) {
  // 1-2 has no speed file at all; the others hold what sysfs never writes, or a cut-off read.
  for (const auto& [usb, text] : std::vector<std::pair<std::string, std::string>>{
           {"3-1.4", "fast\n"}, {"1-5", ""}}) {
    write_usb_file(sysfs(), usb, "speed", text);
    write_usb_file(sysfs(), usb, "version", "two\n");
  }
  SensorCatalog catalog = SensorCatalog::builtin();
  std::ofstream(dir_.file("mine.json")) << R"({"format": "tactile-sensors/1", "sensors": [
      {"model": "Lab webcam GelSight", "vendor_id": "0c45", "product_id": "636d", "product_pattern": "^Integrated"}]})";
  catalog.prepend(SensorCatalog::from_file(dir_.file("mine.json")));
  const auto sensors = discover_sensors(devices(), catalog, sysfs().string());
  ASSERT_EQ(sensors.size(), 3u) << "every sensor is still found";
  for (const auto& s : sensors) {
    EXPECT_FALSE(s.link.speed_mbps) << s.usb.sysfs_name();
    EXPECT_FALSE(s.link.version) << s.usb.sysfs_name();
    EXPECT_EQ(s.link.text(), "speed unknown");
    EXPECT_NE(describe(s).find(") speed unknown  capture /dev/video"), std::string::npos) << describe(s);
    EXPECT_FALSE(s.capture_node.empty()) << s.usb.sysfs_name() << ": its nodes are still found";
  }
  for (const std::string odd : {"53.3-480", "-480", "nan", "0"}) {
    write_usb_file(sysfs(), "1-2", "speed", odd);
    EXPECT_FALSE(read_usb_link(sysfs().string(), "1-2").speed_mbps) << odd;
  }
}

TEST_F(Discovery, FindsTheLinkOfAVideoNode) {
  write_usb_file(sysfs(), "1-2", "speed", "480\n");
  write_usb_file(sysfs(), "3-1.4", "speed", "5000\n");
  EXPECT_EQ(usb_link_of_node(sysfs().string(), "/dev/video2").speed_mbps, 480.0);
  EXPECT_EQ(usb_link_of_node(sysfs().string(), "/dev/video3").speed_mbps, 480.0) << "the metadata node: the same device";
  EXPECT_EQ(usb_link_of_node(sysfs().string(), "/dev/video0").text(), "5000 Mbit/s (USB 3 SuperSpeed)");
  EXPECT_FALSE(usb_link_of_node(sysfs().string(), "/dev/video9").speed_mbps) << "not a USB node";
  EXPECT_FALSE(usb_link_of_node(sysfs().string(), "/dev/video4").speed_mbps) << "a USB node without a speed file";
  EXPECT_FALSE(usb_link_of_node(dir_.file("no-sysfs"), "/dev/video2").speed_mbps);
}

TEST(UsbDevices, ListingWorksWithoutAnySensor) {
  // The test machine has no tactile sensor; listing must still work (or fail with a clear error).
  try {
    const auto devices = list_usb_devices();
    for (const auto& d : devices) EXPECT_FALSE(d.ports.empty());
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("libusb"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace haptex::capture
