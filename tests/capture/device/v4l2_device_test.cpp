// Opening a node, and format and rate negotiation, against the fake camera.
#include <gtest/gtest.h>
#include <linux/videodev2.h>

#include "capture/device/format_negotiation.hpp"
#include "capture/device/v4l2_device.hpp"
#include "core/error.hpp"
#include "tests/capture/fake_setup.hpp"

namespace haptex::capture {
namespace {

std::string refusal(KernelInterface& kernel, const std::string& node) {
  try {
    V4l2Device device(kernel, node);
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::bad_input);
    return e.what();
  }
  ADD_FAILURE() << "opened " << node;
  return {};
}

TEST(V4l2Device, RefusesTheMetadataNodeAndSaysSo) {
  FakeCamera camera;
  const std::string message = refusal(camera, "/dev/video1");
  EXPECT_NE(message.find("/dev/video1"), std::string::npos) << message;
  EXPECT_NE(message.find("metadata node"), std::string::npos) << message;
  EXPECT_NE(message.find("haptex capture devices"), std::string::npos) << message;
  EXPECT_EQ(camera.open_descriptors(), 0u) << "the refused node was closed";
}

TEST(V4l2Device, NamesAMissingNode) {
  FakeCamera camera;
  const std::string message = refusal(camera, "/dev/video9");
  EXPECT_NE(message.find("/dev/video9: no such video device"), std::string::npos) << message;
}

TEST(V4l2Device, ReadsIdentityAndClosesOnDestruction) {
  FakeCamera camera;
  {
    V4l2Device device(camera, "/dev/video0");
    EXPECT_EQ(device.identity().driver, "uvcvideo");
    EXPECT_EQ(device.identity().card, "GelSight Mini R0B 2BNK-CE6G: Ge");
    EXPECT_EQ(camera.open_descriptors(), 1u);
  }
  EXPECT_EQ(camera.open_descriptors(), 0u);
}

TEST(FormatNegotiation, ListsWhatTheNodeOffers) {
  FakeCameraConfig config;
  config.modes = {{V4L2_PIX_FMT_YUYV, 640, 480, {30, 15}}, {V4L2_PIX_FMT_MJPEG, 320, 240, {60, 30}},
                  {V4L2_PIX_FMT_MJPEG, 640, 480, {30}}};
  FakeCamera camera(config);
  V4l2Device device(camera, "/dev/video0");
  const auto offers = enumerate_formats(device);
  ASSERT_EQ(offers.size(), 2u);
  EXPECT_EQ(offers[0].fourcc, V4L2_PIX_FMT_YUYV);
  ASSERT_EQ(offers[1].sizes.size(), 2u);
  EXPECT_EQ(offers[1].sizes[0].width, 640u) << "largest first";
  EXPECT_EQ(offers[1].sizes[1].fps, (std::vector<double>{60, 30}));
}

TEST(FormatNegotiation, DefaultsToMjpgAtTheLargestSizeAndHighestRate) {
  FakeCameraConfig config;
  config.modes = {{V4L2_PIX_FMT_YUYV, 1280, 720, {10}}, {V4L2_PIX_FMT_MJPEG, 320, 240, {60, 30}},
                  {V4L2_PIX_FMT_MJPEG, 640, 480, {30, 15}}};
  FakeCamera camera(config);
  V4l2Device device(camera, "/dev/video0");
  const StreamFormat f = negotiate_format(device, {});
  EXPECT_EQ(f.fourcc, V4L2_PIX_FMT_MJPEG);
  EXPECT_EQ(f.width, 640u);
  EXPECT_EQ(f.height, 480u);
  EXPECT_DOUBLE_EQ(f.fps(), 30.0);
  EXPECT_EQ(f.size_image, 640u * 480u);
}

TEST(FormatNegotiation, TheGelSightMiniGrantsItsOnlyMode) {
  FakeCamera camera;  // MJPG 3280 x 2464 at 25 fps
  V4l2Device device(camera, "/dev/video0");
  FormatRequest request;
  request.fourcc = V4L2_PIX_FMT_MJPEG;
  request.width = 3280;
  request.height = 2464;
  request.fps = 25;
  const StreamFormat f = negotiate_format(device, request);
  EXPECT_EQ(f.width, 3280u);
  EXPECT_DOUBLE_EQ(f.fps(), 25.0);
  EXPECT_DOUBLE_EQ(f.requested_fps, 25.0);
  EXPECT_DOUBLE_EQ(f.period_ns(), 40e6);
}

TEST(FormatNegotiation, RefusesWhatTheNodeLacksListingTheOffers) {
  FakeCamera camera;
  V4l2Device device(camera, "/dev/video0");
  const auto message = [&](FormatRequest r) {
    try {
      negotiate_format(device, r);
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), Error::Kind::bad_input);
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  FormatRequest yuyv;
  yuyv.fourcc = V4L2_PIX_FMT_YUYV;
  EXPECT_NE(message(yuyv).find("YUYV is not offered (the node offers MJPG)"), std::string::npos) << message(yuyv);
  FormatRequest vga;
  vga.width = 640;
  vga.height = 480;
  EXPECT_NE(message(vga).find("640x480 is not offered in MJPG (offered: 3280x2464)"), std::string::npos) << message(vga);
  FormatRequest fast;
  fast.fps = 30;
  EXPECT_NE(message(fast).find("30 fps is not offered at 3280x2464 MJPG (offered: 25 fps)"), std::string::npos)
      << message(fast);
}

TEST(FormatNegotiation, ReportsTheRateOfADriverThatCannotSetOne) {
  FakeCameraConfig config = fixtures::small_camera(V4L2_PIX_FMT_MJPEG, 320, 240, 30);
  config.can_set_rate = false;
  FakeCamera camera(config);
  V4l2Device device(camera, "/dev/video0");
  const StreamFormat f = negotiate_format(device, {});
  EXPECT_DOUBLE_EQ(f.fps(), 30.0);  // read back with G_PARM
}

}  // namespace
}  // namespace haptex::capture
