#include "play/device_name.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <string_view>

#include "core/error.hpp"
#include "core/text/format.hpp"
#include "core/text/utf8.hpp"

namespace haptex::play {
namespace {

bool allowed(char c) { return std::isalnum(static_cast<unsigned char>(c)) || std::string_view("_.:,=-").find(c) != std::string_view::npos; }

}  // namespace

const std::string& checked_device_name(const std::string& device) {
  const std::string fix = "Name a playback device: default, plughw:CARD,DEVICE (aplay -L lists them), or one an ALSA configuration defines; "
                          "--record out.wav keeps what is played";
  if (device.empty()) throw input_error("--device", "", "is empty", fix);
  if (const auto bad = std::find_if_not(device.begin(), device.end(), allowed); bad != device.end())
    throw input_error("--device", "", text::format("'%s' holds '%s' (character %zu), which no device name has: haptex passes ALSA names, not paths, "
                                                   "pipes or definitions", text::printable(device).c_str(), text::printable(std::string(1, *bad)).c_str(),
                                                   std::size_t(bad - device.begin()) + 1),
                      fix);
  // Any word of the string, not only its first: `plug:SLAVE=file:X` opens the file plugin as plug's
  // slave (review 13, F3).
  std::string word;
  for (std::size_t i = 0; i <= device.size(); ++i) {
    if (i < device.size() && std::string_view(":,=").find(device[i]) == std::string_view::npos) {
      word += char(std::tolower(static_cast<unsigned char>(device[i])));
      continue;
    }
    for (const std::string_view writer : std::array<std::string_view, 2>{"file", "tee"})
      if (word == writer)
        throw input_error("--device", "", "'" + text::printable(device) + "' names ALSA's " + std::string(writer) +
                                              " plugin, which writes whatever file its arguments name (or runs a command)",
                          "Keep what is played with --record out.wav; to try play without a card, define a device in an ALSA "
                          "configuration as docs/play.md shows");
    word.clear();
  }
  return device;
}

}  // namespace haptex::play
