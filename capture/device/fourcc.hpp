#pragma once
// V4L2 pixel formats as the four characters users see ("MJPG", "YUYV").
#include <cstdint>
#include <string>
#include <string_view>

namespace haptex::capture {

std::string fourcc_text(std::uint32_t fourcc);
// Throws haptex::Error (bad_input) naming `where` unless text is exactly four printable characters.
std::uint32_t fourcc_code(std::string_view text, const std::string& where);

}  // namespace haptex::capture
