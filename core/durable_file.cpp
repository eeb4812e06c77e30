#include "core/durable_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "core/content_mark.hpp"
#include "core/error.hpp"
#include "core/open_files.hpp"
#include "core/temporary_name.hpp"

namespace haptex {
namespace fs = std::filesystem;

namespace {

std::string directory_of(const std::string& path) {
  fs::path parent = fs::path(path).parent_path();
  return parent.empty() ? "." : parent.string();
}

}  // namespace

std::string why_not_written(int error) {
  return error == ENOSPC || error == EDQUOT ? "the disk is full" : std::strerror(error);
}

void fsync_path(const std::string& path, int flags) {
  int fd = ::open(path.c_str(), flags | O_CLOEXEC);
  if (fd < 0) {
    refuse_if_out_of_descriptors(errno, path);
    throw failure(path + ": cannot open to sync it to disk: " + std::strerror(errno));
  }
  const int status = ::fsync(fd);
  const int saved = errno;
  ::close(fd);
  if (status != 0) throw failure(path + ": cannot write it: " + why_not_written(saved));
}

DirectoryToSync::DirectoryToSync(const std::string& path) : path_(path), fd_(::open(path.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC)) {
  if (fd_ >= 0) return;
  refuse_if_out_of_descriptors(errno, path);
  throw failure(path + ": cannot open to sync it to disk: " + std::strerror(errno));
}

DirectoryToSync::~DirectoryToSync() { ::close(fd_); }

void DirectoryToSync::sync() const {
  if (::fsync(fd_) != 0) throw failure(path_ + ": cannot write it: " + why_not_written(errno));
}

void check_output_path(const std::string& path, bool overwrite) {
  const std::string dir = directory_of(path);
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw input_error(path, "", "the output directory " + dir + " does not exist", "Create it first, or name the output elsewhere");
  if (::access(dir.c_str(), W_OK) != 0)
    throw input_error(path, "", "the output directory " + dir + " is not writable",
                      "Name the output in a directory you can write to");
  require_name_fits(path);
  const fs::file_status link = fs::symlink_status(path, ec);
  if (fs::is_symlink(link) && !fs::exists(path, ec))
    throw input_error(path, "", "the output path is a symbolic link to nothing", "Remove the link, or name the output elsewhere");
  if (!fs::exists(path, ec)) return;
  // Every output comes here (-o, --log, --csv ...): the message names the path, not the option
  // (review 5: train --log FOLDER said "Name a file with -o").
  if (fs::is_directory(path, ec))
    throw input_error(path, "", "the output path is a folder", "Name a file for this output, not a folder");
  if (!fs::is_regular_file(path, ec))  // review 10, C2: a device, FIFO or socket was called a folder
    throw input_error(path, "", "the output path is a device, FIFO or socket, not a file", "Name a regular file for this output");
  if (!overwrite)
    throw input_error(path, "", "the output file already exists", "Remove it, give the output another name, or pass --force");
  // --force swaps out a file, never a link (the swap would replace the link, not what it names): said
  // now, before the work, not when the run is done (review 8).
  if (fs::is_symlink(link))
    throw input_error(path, "", "the output path is a symbolic link, which --force does not replace",
                      "Name the file it points to, or remove the link");
}

void check_replaceable_output(const std::string& path, bool overwrite, const std::string& what,
                              bool (*haptex_wrote)(const std::string& path)) {
  check_output_path(path, overwrite);
  std::error_code ec;
  if (!overwrite || !fs::exists(path, ec)) return;
  if (!haptex_wrote(path))
    throw input_error(path, "", "--force replaces only " + what + ", and this file is not one",
                      "Choose another output name, or move the file away yourself");
  require_content_mark(path);
}

void durable_rename(const std::string& from, const std::string& to, bool replace) {
  const DirectoryToSync folder(directory_of(to));
  int status = replace ? std::rename(from.c_str(), to.c_str()) : ::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_NOREPLACE);
  if (status != 0 && !replace && errno == EINVAL) {  // a file system without RENAME_NOREPLACE: a hard link never replaces either
    status = ::link(from.c_str(), to.c_str());
    if (status == 0) ::unlink(from.c_str());
  }
  if (status != 0 && errno == EEXIST)
    throw input_error(to, "", "appeared while this run was writing it, and is kept: nothing of yours is replaced without --force",
                      "Move it away and run again, or choose another output name");
  if (status != 0) throw failure(from + ": cannot rename to " + to + ": " + std::strerror(errno));
  folder.sync();
}

PartialFile::PartialFile(const std::string& final_path, bool replace, ReplaceableCheck still_replaceable)
    : final_path_(final_path), still_replaceable_(std::move(still_replaceable)), replace_(replace) {
  Temporary t = create_temporary_file(final_path);
  path_ = std::move(t.path);
  fd_ = t.fd;
}

PartialFile::~PartialFile() {
  if (!committed_ && still_names(path_, fd_)) std::remove(path_.c_str());  // what another put there is theirs
  forget_temporary(path_);
  if (fd_ >= 0) ::close(fd_);  // releases the lock
}

void PartialFile::finish() {
  if (finished_) return;
  if (still_replaceable_) mark_content(fd_);  // an output --force may replace later (core/content_mark.hpp)
  if (::fsync(fd_) != 0) throw failure(final_path_ + ": cannot write it: " + why_not_written(errno));
  finished_ = true;
}

void PartialFile::commit() { commit_together({this}); }

void PartialFile::check_place() const {
  std::error_code ec;
  const fs::file_status status = fs::symlink_status(final_path_, ec);
  if (!replace_ && fs::exists(status))
    throw input_error(final_path_, "", "appeared while this run was writing it, and is kept: nothing of yours is replaced without --force",
                      "Move it away and run again, or choose another output name");
  // --force swaps out only a file (checked as haptex's before the work), never a folder or a link that took its place.
  if (replace_ && fs::exists(status) && !fs::is_regular_file(status))
    throw input_error(final_path_, "", "is no longer a file (a folder or a link took its place while this run wrote), and is kept",
                      "Move it away and run again, or choose another output name");
  if (replace_ && fs::exists(status) && still_replaceable_) still_replaceable_(final_path_);
}

void PartialFile::require_not_swapped() const { require_still_named(path_, fd_, final_path_); }

void PartialFile::put_in_place() {
  require_not_swapped();
  rename_into_place();
  placed_ = true;
  if (!still_names(final_path_, fd_)) {
    take_back();
    require_still_named(final_path_, fd_, final_path_);
  }
}

void PartialFile::rename_into_place() {
  std::error_code ec;
  if (!replace_ || !fs::exists(fs::symlink_status(final_path_, ec))) {
    durable_rename(path_, final_path_, false);  // nothing to replace: whatever appears there meanwhile is kept
  } else if (const DirectoryToSync folder(directory_of(final_path_));
             ::renameat2(AT_FDCWD, path_.c_str(), AT_FDCWD, final_path_.c_str(), RENAME_EXCHANGE) == 0) {
    exchanged_ = true;
    folder.sync();
  } else if (errno == EINVAL) {
    durable_rename(path_, final_path_, true);
    replaced_ = true;
  } else {
    throw failure(path_ + ": cannot rename to " + final_path_ + ": " + std::strerror(errno));
  }
}

void PartialFile::take_back() noexcept {
  if (!placed_) return;
  if (exchanged_) ::renameat2(AT_FDCWD, final_path_.c_str(), AT_FDCWD, path_.c_str(), RENAME_EXCHANGE);
  else if (!replaced_) ::rename(final_path_.c_str(), path_.c_str());
  placed_ = exchanged_ = false;
}

void PartialFile::drop_earlier() {
  if (exchanged_) ::unlink(path_.c_str());  // the earlier file, swapped here
  committed_ = true;
  ::close(fd_);  // readers may lock the finished file now
  fd_ = -1;
}

namespace {

// All of bytes to fd; throws haptex::Error (failed) naming `shown` when a write fails.
void write_all(int fd, std::string_view bytes, const std::string& shown) {
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd, bytes.data(), bytes.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw failure(shown + ": cannot write it: " + why_not_written(n < 0 ? errno : ENOSPC));
    bytes.remove_prefix(std::size_t(n));
  }
}

}  // namespace

void write_whole_file(const std::string& path, std::string_view bytes) {
  // A new name in a folder being built: created exclusively, never through a link planted there.
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (fd < 0) throw failure(path + ": cannot create it: " + std::strerror(errno));
  try {
    write_all(fd, bytes, path);
  } catch (...) {
    ::close(fd);
    throw;
  }
  if (::close(fd) != 0) throw failure(path + ": cannot write it: " + why_not_written(errno));
}

void write_text(PartialFile& out, std::string_view text) {
  // Through the descriptor the temporary was created with (O_EXCL | O_NOFOLLOW), never reopened by name.
  write_all(out.fd_, text, out.final_path());
}

void write_file_durably(const std::string& path, std::string_view text, bool replace,
                        PartialFile::ReplaceableCheck still_replaceable) {
  PartialFile partial(path, replace, std::move(still_replaceable));
  write_text(partial, text);
  partial.commit();
}

}  // namespace haptex
