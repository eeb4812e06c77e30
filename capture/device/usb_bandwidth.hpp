#pragma once
// Whether a video mode fits the USB link its sensor negotiated (docs/capture.md, "USB bandwidth").
// A UVC camera streams over one isochronous endpoint, which reserves a fixed share of every bus
// interval; a mode that needs more than that share cannot be carried, whatever the host does, and
// the sensor delivers fewer frames than the driver granted (GelSight Mini users report 15-18 fps of
// the 25 negotiated).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "capture/device/format_negotiation.hpp"
#include "capture/device/usb_discovery.hpp"

namespace haptex::capture {

// MJPG frames vary with the image; this is a low estimate of their size, so that a mode judged too
// big is too big even well compressed. 0.1 bytes (0.8 bits) per pixel, 1/20 of YUYV: the GelSight
// Mini streams 3280 x 2464 MJPG at 25 fps over USB 2.0 high speed (on Windows; gsrobotics issue 6),
// which 196.6 Mbit/s allows only below 0.97 bits per pixel; photographs take 0.7 to 1.2 bits per
// pixel at JPEG quality 50 and 1.3 to 2 at quality 80 (docs/capture.md gives the sources).
inline constexpr double kMjpgBytesPerPixel = 0.1;

// Bytes per second the mode puts on the bus: YUYV exactly (2 bytes per pixel), MJPG estimated with
// kMjpgBytesPerPixel; nullopt for other formats.
std::optional<double> stream_bytes_per_second(std::uint32_t fourcc, std::uint32_t width, std::uint32_t height,
                                              double fps);

// The most one isochronous endpoint moves per second on a link of this speed (Mbit/s, as sysfs
// states it): none at low speed (USB 2.0 section 5.6.3 forbids isochronous transfers there), 1023
// bytes per 1 ms frame at full speed, 3 x 1024 bytes per 125 us microframe at high speed (24.576
// MB/s, 196.6 Mbit/s: USB 2.0 section 5.9, high-bandwidth endpoints), 48 x 1024 bytes per 125 us at
// SuperSpeed (USB 3.0: bursts of 16 packets, Mult 3). Faster links let an endpoint reserve more
// (USB 3.1), so there the link's own rate is the bound: nothing a tactile sensor sends comes near.
double isochronous_bytes_per_second(double link_mbps);

struct LinkBudget {
  double needed = 0, capacity = 0;  // bytes per second
  bool fits() const { return needed <= capacity; }
};

// nullopt when the link's speed or the format's size per frame is unknown: then nothing is said.
std::optional<LinkBudget> link_budget(const StreamFormat& format, const UsbLink& link);

// The warning for a mode that does not fit its link: what it needs, what the link carries, and what
// to do, taken from the node's offers (a faster port when the device supports one, MJPG, a smaller
// size, a lower rate). Empty when the mode fits or the budget is unknown.
std::string link_warning(const std::string& node, const StreamFormat& format, const UsbLink& link,
                         const std::vector<FormatOffer>& offers);

}  // namespace haptex::capture
