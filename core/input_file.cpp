#include "core/input_file.hpp"

#include <linux/magic.h>
#include <sys/stat.h>
#include <sys/vfs.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>

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

void refuse_dangling_link(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_symlink(std::filesystem::symlink_status(path, ec)) && !std::filesystem::exists(path, ec)) require_regular_file(path);
}

void refuse_link_to_its_own_folder(const std::filesystem::path& entry) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_symlink(fs::symlink_status(entry, ec)) || !fs::is_directory(entry, ec)) return;
  const fs::path target = fs::canonical(entry, ec), here = fs::canonical(entry.parent_path(), ec);
  const auto [mismatch, unused] = std::mismatch(target.begin(), target.end(), here.begin(), here.end());
  if (!ec && mismatch == target.end())
    throw input_error(entry.string(), "", "is a link to " + target.string() + ", which holds the folder it is in",
                      "Remove the link, or give the folder it points to as an input of its own");
}

}  // namespace haptex
