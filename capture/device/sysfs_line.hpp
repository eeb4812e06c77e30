#pragma once
// sysfs attributes (/sys/class/video4linux/videoN/name, a USB device's serial ...) are one line of text.
#include <filesystem>
#include <string>

namespace haptex::capture {

// The first line of the file at path, without its newline; "" when it cannot be read (an attribute a
// device or driver does not have).
std::string sysfs_line(const std::filesystem::path& path);

}  // namespace haptex::capture
