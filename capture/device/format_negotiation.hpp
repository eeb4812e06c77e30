#pragma once
// Pixel format, frame size and frame rate: what a node offers (ENUM_FMT, ENUM_FRAMESIZES,
// ENUM_FRAMEINTERVALS) and what it grants when asked (S_FMT, S_PARM). Drivers may round a request,
// so the granted values are what the recorder uses and what the session manifest reports.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "capture/device/v4l2_device.hpp"

namespace haptex::capture {

struct FrameSizeOffer {
  std::uint32_t width = 0, height = 0;
  std::vector<double> fps;  // discrete rates offered at this size, highest first
};

struct FormatOffer {
  std::uint32_t fourcc = 0;
  std::string description;
  std::vector<FrameSizeOffer> sizes;  // largest first
};

// Every format, size and rate the node offers. Stepwise and continuous ranges are reported by
// their smallest and largest size (and rate), which is all `haptex capture devices` shows.
std::vector<FormatOffer> enumerate_formats(const V4l2Device& device);

struct FormatRequest {
  std::optional<std::uint32_t> fourcc;  // default: MJPG when offered (sensors stream it at full size), else the first
  std::optional<std::uint32_t> width, height;  // default: the largest size of that format
  std::optional<double> fps;            // default: the highest rate at that size
};

struct StreamFormat {
  std::uint32_t fourcc = 0, width = 0, height = 0;
  std::uint32_t bytes_per_line = 0, size_image = 0;
  std::uint32_t interval_numerator = 1, interval_denominator = 30;  // seconds per frame, as V4L2 states it
  double requested_fps = 0;  // what was asked for (or chosen from the offers)
  double fps() const { return interval_numerator ? double(interval_denominator) / interval_numerator : 0.0; }
  double period_ns() const { return 1e9 / fps(); }
};

// Chooses from the offers, sets the format and rate, and returns what the driver granted. Throws
// haptex::Error (bad_input) listing the offers when the request names something the node lacks, and
// (failed) when the driver grants another pixel format than the one chosen.
StreamFormat negotiate_format(const V4l2Device& device, const FormatRequest& request);

}  // namespace haptex::capture
