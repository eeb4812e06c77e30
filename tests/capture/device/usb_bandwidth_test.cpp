// The USB bandwidth estimate: what a mode needs, what a link carries for video, and the warning
// with what to do, from the modes the sensor offers.
#include <gtest/gtest.h>
#include <linux/videodev2.h>

#include "capture/device/usb_bandwidth.hpp"

namespace haptex::capture {
namespace {

StreamFormat mode(std::uint32_t fourcc, std::uint32_t width, std::uint32_t height, std::uint32_t fps) {
  StreamFormat f;
  f.fourcc = fourcc;
  f.width = width;
  f.height = height;
  f.interval_numerator = 1;
  f.interval_denominator = fps;
  return f;
}

UsbLink link(double mbps, std::optional<double> version = std::nullopt) { return {mbps, version}; }

// A webcam's offers, as v4l2-ctl --list-formats-ext shows them for many UVC cameras: YUYV only at
// small sizes or low rates, MJPG at full rate.
std::vector<FormatOffer> webcam_offers() {
  return {{V4L2_PIX_FMT_YUYV, "YUYV 4:2:2", {{1280, 720, {30, 10}}, {640, 480, {30}}, {320, 240, {30}}}},
          {V4L2_PIX_FMT_MJPEG, "Motion-JPEG", {{1280, 720, {30}}, {640, 480, {30}}}}};
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(UsbBandwidth, WhatAModeNeeds) {
  EXPECT_EQ(stream_bytes_per_second(V4L2_PIX_FMT_YUYV, 640, 480, 30), 640.0 * 480 * 2 * 30) << "2 bytes per pixel";
  // The GelSight Mini's one mode, at the low MJPG estimate of 0.1 bytes per pixel.
  EXPECT_DOUBLE_EQ(*stream_bytes_per_second(V4L2_PIX_FMT_MJPEG, 3280, 2464, 25), 3280.0 * 2464 * 0.1 * 25);
  EXPECT_FALSE(stream_bytes_per_second(v4l2_fourcc('H', '2', '6', '4'), 1920, 1080, 30)) << "not estimated";
}

TEST(UsbBandwidth, WhatALinkCarriesForVideo) {
  EXPECT_EQ(isochronous_bytes_per_second(1.5), 0.0) << "no isochronous transfers at low speed";
  EXPECT_EQ(isochronous_bytes_per_second(12), 1023000.0) << "1023 bytes per 1 ms frame";
  EXPECT_EQ(isochronous_bytes_per_second(480), 24576000.0) << "3 x 1024 bytes per 125 us microframe";
  EXPECT_NEAR(isochronous_bytes_per_second(480) * 8 / 1e6, 196.6, 0.05) << "far below 480 Mbit/s";
  EXPECT_EQ(isochronous_bytes_per_second(5000), 393216000.0) << "48 x 1024 bytes per 125 us";
  EXPECT_EQ(isochronous_bytes_per_second(10000), 1.25e9);
}

TEST(UsbBandwidth, TheGelSightMiniFitsUsb2AndNotUsb11) {
  const StreamFormat mini = mode(V4L2_PIX_FMT_MJPEG, 3280, 2464, 25);
  ASSERT_TRUE(link_budget(mini, link(480)));
  EXPECT_TRUE(link_budget(mini, link(480))->fits()) << "it streams 25 fps over USB 2.0 on Windows";
  EXPECT_FALSE(link_budget(mini, link(12))->fits());
  EXPECT_FALSE(link_budget(mini, UsbLink{})) << "unknown speed: no judgement";
  EXPECT_EQ(link_warning("/dev/video2", mini, link(480, 2.0), {}), "");
  EXPECT_EQ(link_warning("/dev/video2", mini, UsbLink{}, {}), "") << "the fake camera, or a node without sysfs";
}

TEST(UsbBandwidth, RawHdOverUsb2IsWarnedWithTheFixesTheSensorOffers) {
  // YUYV 1280x720 at 30 fps: 442 Mbit/s of raw frames against 196.6.
  const std::string w = link_warning("/dev/video0", mode(V4L2_PIX_FMT_YUYV, 1280, 720, 30), link(480, 2.0), webcam_offers());
  EXPECT_TRUE(has(w, "/dev/video0: YUYV 1280x720 at 30 fps needs about 442.4 Mbit/s")) << w;
  EXPECT_TRUE(has(w, "its USB link at 480 Mbit/s (USB 2.0 high speed) carries for video (196.6 Mbit/s)")) << w;
  EXPECT_TRUE(has(w, "Try compressed frames (--format MJPG, about 22.1 Mbit/s); ")) << w;
  EXPECT_TRUE(has(w, "; a smaller size (--size 640x480); ")) << "the largest smaller size at 30 fps that fits: " << w;
  EXPECT_TRUE(has(w, "; or a lower rate (--fps 10)")) << w;
  EXPECT_FALSE(has(w, "port")) << "the device is USB 2.0 and runs at 480: no port does better: " << w;
}

TEST(UsbBandwidth, ASensorBehindAUsb11HubIsToldToMove) {
  const StreamFormat mini = mode(V4L2_PIX_FMT_MJPEG, 3280, 2464, 25);
  const std::vector<FormatOffer> only_mode = {{V4L2_PIX_FMT_MJPEG, "Motion-JPEG", {{3280, 2464, {25}}}}};
  const std::string w = link_warning("/dev/video2", mini, link(12, 2.0), only_mode);
  EXPECT_TRUE(has(w, "12 Mbit/s (USB 1.1 full speed)")) << w;
  EXPECT_TRUE(has(w, "Try another port (plug the sensor into a USB 2.0 high speed port or faster directly")) << w;
  EXPECT_FALSE(has(w, "--size")) << "the Mini offers no other size: " << w;
  // Without its USB version the port cannot be judged, and no offered mode fits.
  const std::string unknown = link_warning("/dev/video2", mini, link(12), only_mode);
  EXPECT_TRUE(has(unknown, "No mode the sensor offers fits this link")) << unknown;
}

TEST(UsbBandwidth, LowSpeedCarriesNoVideo) {
  const std::string w = link_warning("/dev/video0", mode(V4L2_PIX_FMT_MJPEG, 320, 240, 30), link(1.5), {});
  EXPECT_TRUE(has(w, "none at low speed")) << w;
}

}  // namespace
}  // namespace haptex::capture
