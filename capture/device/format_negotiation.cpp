#include "capture/device/format_negotiation.hpp"

#include <linux/videodev2.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "capture/device/fourcc.hpp"
#include "core/error.hpp"
#include "core/text/format.hpp"

namespace haptex::capture {
namespace {

std::string size_text(std::uint32_t w, std::uint32_t h) { return std::to_string(w) + "x" + std::to_string(h); }

std::string fps_text(double fps) {
  return text::format("%g", std::round(fps * 1000) / 1000);
}

double interval_fps(const v4l2_fract& interval) {
  return interval.numerator ? double(interval.denominator) / interval.numerator : 0.0;
}

std::vector<double> enumerate_rates(const V4l2Device& device, std::uint32_t fourcc, std::uint32_t w, std::uint32_t h) {
  std::vector<double> rates;
  for (std::uint32_t i = 0;; ++i) {
    v4l2_frmivalenum e{};
    e.index = i;
    e.pixel_format = fourcc;
    e.width = w;
    e.height = h;
    if (device.try_ioctl(VIDIOC_ENUM_FRAMEINTERVALS, &e) != 0) break;
    if (e.type == V4L2_FRMIVAL_TYPE_DISCRETE) {
      rates.push_back(interval_fps(e.discrete));
    } else {  // a range: its fastest and slowest rates
      rates.push_back(interval_fps(e.stepwise.min));
      rates.push_back(interval_fps(e.stepwise.max));
      break;
    }
  }
  std::sort(rates.rbegin(), rates.rend());
  rates.erase(std::unique(rates.begin(), rates.end()), rates.end());
  return rates;
}

std::vector<FrameSizeOffer> enumerate_sizes(const V4l2Device& device, std::uint32_t fourcc) {
  std::vector<FrameSizeOffer> sizes;
  for (std::uint32_t i = 0;; ++i) {
    v4l2_frmsizeenum e{};
    e.index = i;
    e.pixel_format = fourcc;
    if (device.try_ioctl(VIDIOC_ENUM_FRAMESIZES, &e) != 0) break;
    if (e.type == V4L2_FRMSIZE_TYPE_DISCRETE) {
      sizes.push_back({e.discrete.width, e.discrete.height, {}});
    } else {
      sizes.push_back({e.stepwise.max_width, e.stepwise.max_height, {}});
      sizes.push_back({e.stepwise.min_width, e.stepwise.min_height, {}});
      break;
    }
  }
  for (auto& s : sizes) s.fps = enumerate_rates(device, fourcc, s.width, s.height);
  std::stable_sort(sizes.begin(), sizes.end(), [](const FrameSizeOffer& a, const FrameSizeOffer& b) {
    return std::uint64_t(a.width) * a.height > std::uint64_t(b.width) * b.height;
  });
  return sizes;
}

std::string list_formats(const std::vector<FormatOffer>& offers) {
  std::string text;
  for (const auto& f : offers) text += (text.empty() ? "" : ", ") + fourcc_text(f.fourcc);
  return text.empty() ? "none" : text;
}

std::string list_sizes(const FormatOffer& offer) {
  std::string text;
  for (const auto& s : offer.sizes) text += (text.empty() ? "" : ", ") + size_text(s.width, s.height);
  return text;
}

std::string list_rates(const FrameSizeOffer& size) {
  std::string text;
  for (double fps : size.fps) text += (text.empty() ? "" : ", ") + fps_text(fps);
  return text;
}

const FormatOffer& choose_format(const V4l2Device& device, const std::vector<FormatOffer>& offers,
                                 const FormatRequest& request) {
  if (offers.empty())
    throw input_error(device.path(), "VIDIOC_ENUM_FMT", "the node offers no pixel format", "Is it a camera?");
  const std::uint32_t wanted = request.fourcc.value_or(v4l2_fourcc('M', 'J', 'P', 'G'));
  for (const auto& f : offers)
    if (f.fourcc == wanted) return f;
  if (!request.fourcc) return offers.front();
  throw input_error(device.path(), "pixel format", fourcc_text(wanted) + " is not offered (the node offers " +
                                                       list_formats(offers) + ")",
                    "Choose one of those with --format");
}

const FrameSizeOffer& choose_size(const V4l2Device& device, const FormatOffer& format, const FormatRequest& request) {
  if (format.sizes.empty())
    throw input_error(device.path(), "VIDIOC_ENUM_FRAMESIZES", fourcc_text(format.fourcc) + " offers no frame size",
                      "Choose another --format");
  if (!request.width) return format.sizes.front();
  for (const auto& s : format.sizes)
    if (s.width == *request.width && s.height == *request.height) return s;
  throw input_error(device.path(), "frame size",
                    size_text(*request.width, *request.height) + " is not offered in " + fourcc_text(format.fourcc) +
                        " (offered: " + list_sizes(format) + ")",
                    "Choose one of those with --size");
}

double choose_rate(const V4l2Device& device, const FormatOffer& format, const FrameSizeOffer& size,
                   const FormatRequest& request) {
  if (size.fps.empty()) return request.fps.value_or(0.0);  // the driver lists no rates; ask and see
  if (!request.fps) return size.fps.front();
  for (double fps : size.fps)
    if (std::abs(fps - *request.fps) <= 0.01 * *request.fps) return fps;
  throw input_error(device.path(), "frame rate",
                    fps_text(*request.fps) + " fps is not offered at " + size_text(size.width, size.height) + " " +
                        fourcc_text(format.fourcc) + " (offered: " + list_rates(size) + " fps)",
                    "Choose one of those with --fps");
}

void set_format(const V4l2Device& device, StreamFormat& out) {
  v4l2_format f{};
  f.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  f.fmt.pix.pixelformat = out.fourcc;
  f.fmt.pix.width = out.width;
  f.fmt.pix.height = out.height;
  f.fmt.pix.field = V4L2_FIELD_ANY;
  device.ioctl_or_throw(VIDIOC_S_FMT, &f, "VIDIOC_S_FMT (" + fourcc_text(out.fourcc) + " " + size_text(out.width, out.height) + ")");
  if (f.fmt.pix.pixelformat != out.fourcc)
    throw failure(device.path() + ": asked for " + fourcc_text(out.fourcc) + ", the driver granted " +
                  fourcc_text(f.fmt.pix.pixelformat) + "; choose a format it keeps with --format");
  out.width = f.fmt.pix.width;
  out.height = f.fmt.pix.height;
  out.bytes_per_line = f.fmt.pix.bytesperline;
  out.size_image = f.fmt.pix.sizeimage;
}

void set_rate(const V4l2Device& device, double fps, StreamFormat& out) {
  v4l2_streamparm parm{};
  parm.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  if (fps > 0) {
    // 1/fps as a fraction V4L2 drivers match exactly: 1/25, 1/30, 1001/30000 ...
    const bool whole = std::abs(fps - std::round(fps)) < 1e-6;
    parm.parm.capture.timeperframe = whole ? v4l2_fract{1, std::uint32_t(std::lround(fps))}
                                           : v4l2_fract{1000, std::uint32_t(std::lround(fps * 1000))};
    if (device.try_ioctl(VIDIOC_S_PARM, &parm) == 0 && parm.parm.capture.timeperframe.numerator) {
      out.interval_numerator = parm.parm.capture.timeperframe.numerator;
      out.interval_denominator = parm.parm.capture.timeperframe.denominator;
      return;
    }
  }
  // The driver cannot set a rate (no V4L2_CAP_TIMEPERFRAME): report the one it runs at.
  parm = {};
  parm.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  if (device.try_ioctl(VIDIOC_G_PARM, &parm) == 0 && parm.parm.capture.timeperframe.numerator) {
    out.interval_numerator = parm.parm.capture.timeperframe.numerator;
    out.interval_denominator = parm.parm.capture.timeperframe.denominator;
  } else if (fps > 0) {
    out.interval_numerator = 1000;
    out.interval_denominator = std::uint32_t(std::lround(fps * 1000));
  } else {
    throw failure(device.path() + ": the driver reports no frame rate; give one with --fps");
  }
}

}  // namespace

std::vector<FormatOffer> enumerate_formats(const V4l2Device& device) {
  std::vector<FormatOffer> offers;
  for (std::uint32_t i = 0;; ++i) {
    v4l2_fmtdesc d{};
    d.index = i;
    d.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    if (device.try_ioctl(VIDIOC_ENUM_FMT, &d) != 0) break;
    const char* text = reinterpret_cast<const char*>(d.description);
    offers.push_back({d.pixelformat, std::string(text, strnlen(text, sizeof d.description)), {}});
  }
  for (auto& f : offers) f.sizes = enumerate_sizes(device, f.fourcc);
  return offers;
}

StreamFormat negotiate_format(const V4l2Device& device, const FormatRequest& request) {
  const std::vector<FormatOffer> offers = enumerate_formats(device);
  const FormatOffer& format = choose_format(device, offers, request);
  const FrameSizeOffer& size = choose_size(device, format, request);
  StreamFormat out;
  out.fourcc = format.fourcc;
  out.width = size.width;
  out.height = size.height;
  out.requested_fps = choose_rate(device, format, size, request);
  set_format(device, out);
  set_rate(device, out.requested_fps, out);
  return out;
}

}  // namespace haptex::capture
