// `haptex capture devices` on a machine without a tactile sensor (the test machine), and its errors.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/support/run_haptex.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {

TEST(CaptureDevicesCli, SaysSoWhenNoSensorIsConnected) {
  const CommandResult json = run_haptex({"capture", "devices", "--json"});
  ASSERT_EQ(json.exit_code, 0) << json.err;
  const nlohmann::json doc = nlohmann::json::parse(json.out);
  ASSERT_TRUE(doc["sensors"].is_array());
  if (!doc["sensors"].empty()) GTEST_SKIP() << "a tactile sensor is connected to this machine";
  const CommandResult r = run_haptex({"capture", "devices"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("no tactile sensor found"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("GelSight Mini (0c45:636d)"), std::string::npos) << r.out;
}

TEST(CaptureDevicesCli, RefusesABadSensorListWithOneMessage) {
  TempDir dir;
  std::ofstream(dir.file("sensors.json")) << R"({"format": "tactile-sensors/1", "sensors": [{"model": "X"}]})";
  const CommandResult r = run_haptex({"capture", "devices", "--sensors", dir.file("sensors.json")});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("sensors.json: /sensors/0"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

}  // namespace
}  // namespace haptex::test
