#pragma once
// The first check on every file haptex reads: that it is there and is a regular file. A FIFO, a socket
// or a device (/dev/zero) would block a reader forever or never end, so it is refused by name before
// anything opens it, as replay always did; a folder where a file is expected is refused the same way,
// and so is a file of the kernel's own file systems (/proc, /sys), which stats as regular.
#include <string>

namespace haptex {

// Throws haptex::Error (bad_input) naming path and the fix: missing, a folder, or not a regular file
// (saying which kind). A symbolic link to a regular file passes.
void require_regular_file(const std::string& path);

}  // namespace haptex
