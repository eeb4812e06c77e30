#include "convert/recording.hpp"

#include <algorithm>

namespace haptex::convert {

bool is_required_channel(const std::string& channel) {
  return std::find(kRequiredChannels.begin(), kRequiredChannels.end(), channel) != kRequiredChannels.end();
}

std::string quantity_of(const std::string& channel) {
  if (channel.rfind("accel", 0) == 0) return "accel";
  if (channel.rfind("force", 0) == 0) return "force";
  if (channel.rfind("position", 0) == 0) return "position";
  return "speed";
}

}  // namespace haptex::convert
