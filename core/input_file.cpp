#include "core/input_file.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>

#include "core/error.hpp"

namespace haptex {

void require_regular_file(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    struct stat link {};
    if (errno == ENOENT && ::lstat(path.c_str(), &link) == 0)
      throw input_error(path, "", "is a symbolic link to a file that does not exist", "Point the link at the file, or give the file");
    if (errno == ENOENT || errno == ENOTDIR) throw input_error(path, "", "no such file", "Check the path");
    throw input_error(path, "", std::string("cannot look at the file: ") + std::strerror(errno), "Check the path and permissions");
  }
  if (S_ISREG(st.st_mode)) return;
  if (S_ISDIR(st.st_mode)) throw input_error(path, "", "is a folder, not a file", "Name the file inside it");
  const char* kind = S_ISFIFO(st.st_mode) ? "a FIFO (named pipe)" : S_ISSOCK(st.st_mode) ? "a socket" : "a device";
  throw input_error(path, "", std::string("is ") + kind + ", not a regular file, and haptex reads only regular files",
                    "Save what it carries to a file first, and give that file");
}

}  // namespace haptex
