#include "core/durable_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "core/error.hpp"

namespace haptex {
namespace fs = std::filesystem;

namespace {

std::string directory_of(const std::string& path) {
  fs::path parent = fs::path(path).parent_path();
  return parent.empty() ? "." : parent.string();
}

void fsync_path(const std::string& path, int flags) {
  int fd = ::open(path.c_str(), flags);
  if (fd < 0) throw failure(path + ": cannot open to sync it to disk: " + std::strerror(errno));
  const int status = ::fsync(fd);
  const int saved = errno;
  ::close(fd);
  if (status != 0) throw failure(path + ": fsync failed: " + std::strerror(saved));
}

}  // namespace

void check_output_path(const std::string& path, bool overwrite) {
  const std::string dir = directory_of(path);
  if (!fs::is_directory(dir))
    throw input_error(path, "", "the output directory " + dir + " does not exist", "Create it first or choose another -o");
  if (::access(dir.c_str(), W_OK) != 0)
    throw input_error(path, "", "the output directory " + dir + " is not writable",
                      "Choose a directory you can write to with -o");
  if (fs::exists(path) && !overwrite)
    throw input_error(path, "", "the output file already exists", "Remove it, choose another -o, or pass --force");
}

std::string create_partial(const std::string& final_path) {
  const std::string partial = final_path + ".partial";
  int fd = ::open(partial.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0)
    throw input_error(final_path, "", std::string("cannot create the output file: ") + std::strerror(errno),
                      "Choose a directory you can write to with -o");
  ::close(fd);
  return partial;
}

void durable_rename(const std::string& from, const std::string& to) {
  fsync_path(from, O_RDONLY);
  if (std::rename(from.c_str(), to.c_str()) != 0)
    throw failure(from + ": cannot rename to " + to + ": " + std::strerror(errno));
  fsync_path(directory_of(to), O_RDONLY | O_DIRECTORY);
}

}  // namespace haptex
