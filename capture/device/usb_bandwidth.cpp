#include "capture/device/usb_bandwidth.hpp"

#include <linux/videodev2.h>

#include <cmath>
#include <cstdio>

#include "capture/device/fourcc.hpp"
#include "core/text/format.hpp"

namespace haptex::capture {
namespace {

std::string mbit_text(double bytes_per_second) {
  return text::format("%.1f Mbit/s", bytes_per_second * 8 / 1e6);
}

std::string number_text(double value) {
  return text::format("%g", std::round(value * 1000) / 1000);
}

bool fits(std::uint32_t fourcc, std::uint32_t width, std::uint32_t height, double fps, double capacity) {
  const std::optional<double> needed = stream_bytes_per_second(fourcc, width, height, fps);
  return needed && *needed <= capacity;
}

// Offered rates are matched as negotiation matches them: within 1 %.
bool at_least(double offered, double fps) { return offered >= 0.99 * fps; }

const FormatOffer* offer_of(const std::vector<FormatOffer>& offers, std::uint32_t fourcc) {
  for (const auto& offer : offers)
    if (offer.fourcc == fourcc) return &offer;
  return nullptr;
}

using Remedy = std::optional<std::string>;

// The same mode over the link the device supports, when that link would carry it.
Remedy faster_port(const UsbLink& link, double needed) {
  const std::optional<double> faster = link.faster_speed_possible();
  if (!faster || needed > isochronous_bytes_per_second(*faster)) return std::nullopt;
  return "another port (plug the sensor into a " + usb_speed_name(*faster) + " port or faster directly, not through a "
         "hub, an extension cable or a dock: the device supports it, but its link runs at " + number_text(*link.speed_mbps) +
         " Mbit/s)";
}

// MJPG at the same size and rate.
Remedy compressed(const StreamFormat& f, const std::vector<FormatOffer>& offers, double capacity) {
  const FormatOffer* mjpg = offer_of(offers, V4L2_PIX_FMT_MJPEG);
  if (f.fourcc == V4L2_PIX_FMT_MJPEG || !mjpg) return std::nullopt;
  for (const auto& size : mjpg->sizes)
    if (size.width == f.width && size.height == f.height)
      for (double fps : size.fps)
        if (at_least(fps, f.fps()) && fits(mjpg->fourcc, f.width, f.height, f.fps(), capacity))
          return "compressed frames (--format MJPG, about " +
                 mbit_text(*stream_bytes_per_second(mjpg->fourcc, f.width, f.height, f.fps())) + ")";
  return std::nullopt;
}

// The largest smaller size of the same format offered at the same rate that fits.
Remedy smaller_size(const StreamFormat& f, const std::vector<FormatOffer>& offers, double capacity) {
  const FormatOffer* same = offer_of(offers, f.fourcc);
  if (!same) return std::nullopt;
  for (const auto& size : same->sizes)  // largest first
    if (std::uint64_t(size.width) * size.height < std::uint64_t(f.width) * f.height)
      for (double fps : size.fps)
        if (at_least(fps, f.fps()) && fits(f.fourcc, size.width, size.height, f.fps(), capacity))
          return "a smaller size (--size " + std::to_string(size.width) + "x" + std::to_string(size.height) + ")";
  return std::nullopt;
}

// The highest lower rate offered at this format and size that fits.
Remedy lower_rate(const StreamFormat& f, const std::vector<FormatOffer>& offers, double capacity) {
  const FormatOffer* same = offer_of(offers, f.fourcc);
  if (!same) return std::nullopt;
  for (const auto& size : same->sizes)
    if (size.width == f.width && size.height == f.height)
      for (double fps : size.fps)  // highest first
        if (fps < 0.99 * f.fps() && fits(f.fourcc, f.width, f.height, fps, capacity)) return "a lower rate (--fps " + number_text(fps) + ")";
  return std::nullopt;
}

}  // namespace

std::optional<double> stream_bytes_per_second(std::uint32_t fourcc, std::uint32_t width, std::uint32_t height,
                                              double fps) {
  const double pixels = double(width) * double(height);
  if (fourcc == V4L2_PIX_FMT_YUYV) return pixels * 2.0 * fps;
  if (fourcc == V4L2_PIX_FMT_MJPEG) return pixels * kMjpgBytesPerPixel * fps;
  return std::nullopt;
}

double isochronous_bytes_per_second(double link_mbps) {
  if (link_mbps < 12) return 0;                        // low speed: no isochronous transfers
  if (link_mbps < 480) return 1023.0 * 1000;           // full speed: 1023 bytes per 1 ms frame
  if (link_mbps < 5000) return 3.0 * 1024 * 8000;      // high speed: 3 x 1024 bytes per 125 us microframe
  if (link_mbps < 10000) return 48.0 * 1024 * 8000;    // SuperSpeed: 16-packet bursts x Mult 3 per 125 us
  return link_mbps * 1e6 / 8;                          // SuperSpeed+: the link's rate bounds it
}

std::optional<LinkBudget> link_budget(const StreamFormat& format, const UsbLink& link) {
  if (!link.speed_mbps) return std::nullopt;
  const std::optional<double> needed = stream_bytes_per_second(format.fourcc, format.width, format.height, format.fps());
  if (!needed) return std::nullopt;
  return LinkBudget{*needed, isochronous_bytes_per_second(*link.speed_mbps)};
}

std::string link_warning(const std::string& node, const StreamFormat& format, const UsbLink& link,
                         const std::vector<FormatOffer>& offers) {
  const std::optional<LinkBudget> budget = link_budget(format, link);
  if (!budget || budget->fits()) return "";
  std::string text = node + ": " + fourcc_text(format.fourcc) + " " + std::to_string(format.width) + "x" +
                     std::to_string(format.height) + " at " + number_text(format.fps()) + " fps needs about " +
                     mbit_text(budget->needed) +
                     (format.fourcc == V4L2_PIX_FMT_MJPEG ? " (MJPG estimated at 0.8 bits per pixel)" : "") +
                     ", more than its USB link at " + link.text() + " carries for video (" +
                     (budget->capacity > 0 ? mbit_text(budget->capacity) : std::string("none at low speed")) +
                     "): the sensor will deliver fewer frames per second than granted. ";
  std::vector<std::string> fixes;
  for (const Remedy& r : {faster_port(link, budget->needed), compressed(format, offers, budget->capacity),
                          smaller_size(format, offers, budget->capacity), lower_rate(format, offers, budget->capacity)})
    if (r) fixes.push_back(*r);
  if (fixes.empty()) return text + "No mode the sensor offers fits this link: connect it to a faster port";
  text += "Try ";
  for (std::size_t i = 0; i < fixes.size(); ++i) text += (i == 0 ? "" : i + 1 == fixes.size() ? "; or " : "; ") + fixes[i];
  return text;
}

}  // namespace haptex::capture
