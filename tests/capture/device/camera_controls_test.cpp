// Exposure, white balance and gain are locked before recording.
#include <gtest/gtest.h>
#include <linux/videodev2.h>

#include "capture/device/camera_controls.hpp"
#include "core/error.hpp"
#include "tests/capture/fake_setup.hpp"

namespace haptex::capture {
namespace {

const LockedControl* find(const ControlLock& lock, std::uint32_t id) {
  for (const auto& c : lock.locked)
    if (c.id == id) return &c;
  return nullptr;
}

TEST(CameraControls, SwitchesAutomaticModesOffAndPinsTheSettledValues) {
  FakeCamera camera;
  V4l2Device device(camera, "/dev/video0");
  const ControlLock lock = lock_controls(device, {});
  EXPECT_EQ(camera.control_value(V4L2_CID_EXPOSURE_AUTO), V4L2_EXPOSURE_MANUAL);
  EXPECT_EQ(camera.control_value(V4L2_CID_EXPOSURE_AUTO_PRIORITY), 0);
  EXPECT_EQ(camera.control_value(V4L2_CID_AUTO_WHITE_BALANCE), 0);
  // The values the automatic loops had settled on (the fake's 166 and 5120), not the defaults.
  EXPECT_EQ(camera.control_value(V4L2_CID_EXPOSURE_ABSOLUTE), 166);
  ASSERT_NE(find(lock, V4L2_CID_EXPOSURE_ABSOLUTE), nullptr);
  EXPECT_EQ(find(lock, V4L2_CID_EXPOSURE_ABSOLUTE)->value, 166);
  EXPECT_FALSE(find(lock, V4L2_CID_EXPOSURE_ABSOLUTE)->requested);
  EXPECT_EQ(find(lock, V4L2_CID_WHITE_BALANCE_TEMPERATURE)->value, 5120);
  EXPECT_EQ(find(lock, V4L2_CID_GAIN)->value, 32);
  // UVC cameras rarely have automatic gain: reported, not fatal.
  EXPECT_EQ(lock.missing, (std::vector<std::string>{"gain_automatic"}));
}

TEST(CameraControls, GivenValuesWinAndOldNamesWork) {
  FakeCamera camera;
  V4l2Device device(camera, "/dev/video0");
  const ControlLock lock = lock_controls(device, {{control_id("exposure_absolute"), 300},
                                                  {control_id("white_balance_temperature"), 4000},
                                                  {control_id("brightness"), 5}});
  EXPECT_EQ(camera.control_value(V4L2_CID_EXPOSURE_ABSOLUTE), 300);
  EXPECT_TRUE(find(lock, V4L2_CID_EXPOSURE_ABSOLUTE)->requested);
  EXPECT_EQ(camera.control_value(V4L2_CID_WHITE_BALANCE_TEMPERATURE), 4000);
  EXPECT_EQ(camera.control_value(V4L2_CID_BRIGHTNESS), 5);
}

TEST(CameraControls, NamesOfBothKernelGenerations) {
  EXPECT_EQ(control_id("exposure_auto"), control_id("auto_exposure"));
  EXPECT_EQ(control_id("exposure_absolute"), std::uint32_t(V4L2_CID_EXPOSURE_ABSOLUTE));
  EXPECT_EQ(control_id("exposure_time_absolute"), std::uint32_t(V4L2_CID_EXPOSURE_ABSOLUTE));
  EXPECT_EQ(control_id("white_balance_temperature_auto"), control_id("white_balance_automatic"));
  EXPECT_EQ(control_id("autogain"), control_id("gain_automatic"));
  EXPECT_EQ(control_id("0x009a0902"), std::uint32_t(V4L2_CID_EXPOSURE_ABSOLUTE));
  EXPECT_EQ(control_name(V4L2_CID_EXPOSURE_ABSOLUTE), "exposure_time_absolute");
  EXPECT_THROW(control_id("exposure_magic"), Error);
}

TEST(CameraControls, RefusesOutOfRangeValuesAndControlsTheDeviceLacks) {
  FakeCamera camera;
  V4l2Device device(camera, "/dev/video0");
  try {
    lock_controls(device, {{V4L2_CID_EXPOSURE_ABSOLUTE, 99999}});
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::bad_input);
    EXPECT_NE(std::string(e.what()).find("outside the control's range 1..5000"), std::string::npos) << e.what();
  }
  try {
    lock_controls(device, {{V4L2_CID_SHARPNESS, 3}});
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("sharpness: the device has no such control"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace haptex::capture
