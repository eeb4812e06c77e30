#include "capture/device/sysfs_line.hpp"

#include <fstream>

namespace haptex::capture {

std::string sysfs_line(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  return line;
}

}  // namespace haptex::capture
