#include "convert/recording.hpp"

namespace haptex::convert {

std::string quantity_of(const std::string& channel) {
  if (channel.rfind("accel", 0) == 0) return "accel";
  if (channel.rfind("force", 0) == 0) return "force";
  if (channel.rfind("position", 0) == 0) return "position";
  return "speed";
}

}  // namespace haptex::convert
