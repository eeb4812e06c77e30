#include "capture/device/fourcc.hpp"

#include <cctype>

#include "core/error.hpp"

namespace haptex::capture {

std::string fourcc_text(std::uint32_t fourcc) {
  std::string text;
  for (int i = 0; i < 4; ++i) {
    const char c = static_cast<char>((fourcc >> (8 * i)) & 0xff);
    text += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
  }
  return text;
}

std::uint32_t fourcc_code(std::string_view text, const std::string& where) {
  bool printable = text.size() == 4;
  for (char c : text) printable = printable && std::isprint(static_cast<unsigned char>(c));
  if (!printable)
    throw input_error(where, "pixel format", "'" + std::string(text) + "' is not a four-character code",
                      "Give a V4L2 format such as MJPG or YUYV ('v4l2-ctl --list-formats' lists a device's)");
  std::uint32_t code = 0;
  for (int i = 0; i < 4; ++i) code |= std::uint32_t(static_cast<unsigned char>(text[i])) << (8 * i);
  return code;
}

}  // namespace haptex::capture
