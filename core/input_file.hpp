#pragma once
// The first check on every file haptex reads: that it is there and is a regular file. A FIFO, a socket
// or a device (/dev/zero) would block a reader forever or never end, so it is refused by name before
// anything opens it, as replay always did; a folder where a file is expected is refused the same way,
// and so is a file of the kernel's own file systems (/proc, /sys), which stats as regular.
#include <filesystem>
#include <string>

namespace haptex {

// Throws haptex::Error (bad_input) naming path and the fix: missing, a folder, or not a regular file
// (saying which kind). A symbolic link to a regular file passes.
void require_regular_file(const std::string& path);

// For an entry met while reading a folder: a symbolic link to nothing (a moved or unmounted disk) is
// refused by name whatever its name, since what it stood for (a material's folder, a video, a folder
// of recordings) would otherwise be missing without a word (review 14, F8). Throws as above.
void refuse_dangling_link(const std::string& path);
// For an entry met while reading a folder: a link to that folder or to one holding it (`loop -> ../..`)
// would read everything around the input, or forever; it is refused by its own name.
void refuse_link_to_its_own_folder(const std::filesystem::path& entry);

}  // namespace haptex
