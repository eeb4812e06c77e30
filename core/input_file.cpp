#include "core/input_file.hpp"

#include <linux/magic.h>
#include <sys/stat.h>
#include <sys/vfs.h>

#include <cerrno>
#include <cstring>

#include "core/error.hpp"

namespace haptex {

namespace {

// Files of the kernel's own file systems stat as regular, yet some never end or block in read()
// (/proc/kmsg, tracefs's trace_pipe): review 9, F2.
bool on_kernel_file_system(const std::string& path) {
  struct statfs fs {};
  if (::statfs(path.c_str(), &fs) != 0) return false;
  for (const auto magic : {PROC_SUPER_MAGIC, SYSFS_MAGIC, DEBUGFS_MAGIC, TRACEFS_MAGIC})
    if (fs.f_type == decltype(fs.f_type)(magic)) return true;
  return false;
}

}  // namespace

void require_regular_file(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    struct stat link {};
    if (errno == ENOENT && ::lstat(path.c_str(), &link) == 0)
      throw input_error(path, "", "is a symbolic link to a file that does not exist", "Point the link at the file, or give the file");
    if (errno == ENOENT || errno == ENOTDIR) throw input_error(path, "", "no such file", "Check the path");
    throw input_error(path, "", std::string("cannot look at the file: ") + std::strerror(errno), "Check the path and permissions");
  }
  if (S_ISREG(st.st_mode) && on_kernel_file_system(path))
    throw input_error(path, "", "is a file of the kernel (/proc, /sys), which may block or never end, not a file on a disk",
                      "Save what it holds to a file first (cat it into one), and give that file");
  if (S_ISREG(st.st_mode)) return;
  if (S_ISDIR(st.st_mode)) throw input_error(path, "", "is a folder, not a file", "Name the file inside it");
  const char* kind = S_ISFIFO(st.st_mode) ? "a FIFO (named pipe)" : S_ISSOCK(st.st_mode) ? "a socket" : "a device";
  throw input_error(path, "", std::string("is ") + kind + ", not a regular file, and haptex reads only regular files",
                    "Save what it carries to a file first, and give that file");
}

}  // namespace haptex
