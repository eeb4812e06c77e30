#pragma once
// What --device may name (docs/play.md, "Devices"). An ALSA device string is a small configuration
// language: `file:FILE=model.h5` truncates any file, the command's own input included, and
// `file:FILE=|cmd` runs cmd through a shell (review 12, F3). So haptex passes ALSA a device name
// only: letters, digits and `_ . : , = -` (default, plughw:1,0, hw:CARD=PCH,DEV=0, sysdefault:CARD=x,
// a name an ALSA configuration defines), never naming the file-writing plugins (`file`, `tee`) in any
// part of it, and never a path, a pipe or an inline definition.
#include <string>

namespace haptex::play {

// Returns `device` when it names a device as above; throws haptex::Error (bad_input) naming --device,
// the first character refused or the plugin, and the fix otherwise.
const std::string& checked_device_name(const std::string& device);

}  // namespace haptex::play
