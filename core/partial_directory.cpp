#include "core/partial_directory.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "core/durable_file.hpp"
#include "core/error.hpp"
#include "core/output_is_input.hpp"
#include "core/owned_folder.hpp"
#include "core/temporary_name.hpp"

namespace haptex {
namespace fs = std::filesystem;
namespace {

std::string trimmed(std::string path) {
  while (path.size() > 1 && path.back() == '/') path.pop_back();
  return path;
}

std::string parent_of(const std::string& path) {
  const fs::path parent = fs::path(path).parent_path();
  return parent.empty() ? "." : parent.string();
}

bool empty_folder(const std::string& dir) {
  std::error_code ec;
  return fs::is_empty(dir, ec) && !ec;
}

}  // namespace

// May `dir` become (or replace) the folder? Throws bad_input saying why not.
void check_folder_destination(const std::string& path, const FolderOptions& o) {
  const std::string dir = trimmed(path);
  const std::string name = fs::path(dir).filename().string();
  if (name.empty() || name == "." || name == "..")
    throw input_error(dir, "", "not a name for a new " + o.what, "Name the folder with " + o.option);
  const std::string parent = parent_of(dir);
  std::error_code ec;
  if (!fs::is_directory(parent, ec))
    throw input_error(dir, "", "the folder " + parent + " that should hold the " + o.what + " does not exist",
                      "Create it first or choose another " + o.option);
  if (::access(parent.c_str(), W_OK) != 0)
    throw input_error(dir, "", "the folder " + parent + " is not writable", "Choose a folder you can write to with " + o.option);
  const fs::file_status status = fs::symlink_status(dir, ec);
  if (!fs::exists(status)) return;
  if (fs::is_symlink(status))  // review 9, C6: "not a folder" for a link to one misled
    throw input_error(dir, "", "is a symbolic link, which haptex never writes through or replaces",
                      "Remove the link, or choose another " + o.option);
  if (!fs::is_directory(status))
    throw input_error(dir, "", "exists and is not a folder", "Choose another " + o.option + ", or move it out of the way");
  if (!o.overwrite && !empty_folder(dir))
    throw input_error(dir, "", "the " + o.what + " already exists and is not empty",
                      "Remove it, choose another " + o.option + ", or pass --force to replace it");
  check_only_haptex_files(dir, o.written_by);
}

namespace {

// Every file and folder under dir, deepest first, then dir itself.
void fsync_tree(const std::string& dir) {
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    if (entry.is_directory())
      fsync_tree(entry.path().string());
    else
      fsync_path(entry.path().string(), O_RDONLY);
  }
  fsync_path(dir, O_RDONLY | O_DIRECTORY);
}

}  // namespace

PartialDirectory::PartialDirectory(std::string final_path, FolderOptions options)
    : final_(trimmed(std::move(final_path))), options_(std::move(options)) {
  check_folder_destination(final_, options_);
  Temporary t = create_temporary_folder(final_);
  path_ = std::move(t.path);
  fd_ = t.fd;
}

PartialDirectory::~PartialDirectory() {
  std::error_code ignored;
  if (!committed_ && still_names(path_, fd_)) fs::remove_all(path_, ignored);  // a folder put there by another is theirs
  forget_temporary(path_);
  if (fd_ >= 0) ::close(fd_);
}

void PartialDirectory::fill(const std::function<void(const std::string& dir)>& write) const {
  try {
    write(path_);
  } catch (const Error& e) {
    throw renamed_in(e, path_, final_);
  }
}

void PartialDirectory::finish() {
  if (finished_) return;
  fill([&](const std::string& dir) {
    write_file_list(dir, options_.written_by, owner_);
    fsync_tree(dir);
  });
  finished_ = true;
}

void PartialDirectory::commit() { commit_together({this}); }

void PartialDirectory::belongs_to(const std::string& output) {
  // Review 31, F5: a folder whose list names another output, still there, as its owner is that
  // output's companion (a.h5's sheets), which --force over this output does not take.
  const std::string earlier = folder_owner(final_);
  std::error_code ec;
  if (!earlier.empty() && !same_output_path(earlier, output) && fs::exists(fs::symlink_status(earlier, ec)))
    throw input_error(final_, "", "is the " + options_.what + " of " + earlier + ", which is still there (its " + std::string(kFileListName) + " names it)",
                      "Give " + options_.option + " another folder, or remove " + earlier + " first");
  // The folder's own place, not its temporary one: the list is read there.
  owner_ = std::filesystem::absolute(output).lexically_relative(std::filesystem::absolute(final_)).string();
}

void PartialDirectory::check_place() const {
  std::error_code ec;
  if (fs::exists(fs::symlink_status(final_, ec))) check_folder_destination(final_, options_);  // it appeared, or got a file of the user's
}

void PartialDirectory::put_in_place() {
  require_still_named(path_, fd_, final_);  // a link or a folder of someone else's swapped in (review 14, F1)
  std::error_code ec;
  const bool replace = fs::exists(fs::symlink_status(final_, ec));
  const DirectoryToSync parent(parent_of(final_));  // before the rename: core/durable_file.hpp
  int status = ::renameat2(AT_FDCWD, path_.c_str(), AT_FDCWD, final_.c_str(), replace ? RENAME_EXCHANGE : RENAME_NOREPLACE);
  if (status != 0 && !replace && errno == EINVAL) status = std::rename(path_.c_str(), final_.c_str());  // no RENAME_NOREPLACE here
  if (status != 0 && !replace && errno == EEXIST)
    throw input_error(final_, "", "appeared while this run was writing the " + options_.what + ", and is kept",
                      "Move it away and run again, or choose another " + options_.option);
  if (status != 0)
    throw failure(path_ + ": cannot rename to " + final_ + ": " + std::strerror(errno) +
                  (replace ? " (remove the old " + options_.what + " and run again)" : ""));
  placed_ = true;
  exchanged_ = replace;
  if (!still_names(final_, fd_)) {  // the swap came between the check and the rename
    take_back();
    require_still_named(final_, fd_, final_);
  }
  parent.sync();
}

void PartialDirectory::take_back() noexcept {
  if (!placed_) return;
  if (exchanged_) ::renameat2(AT_FDCWD, final_.c_str(), AT_FDCWD, path_.c_str(), RENAME_EXCHANGE);
  else ::rename(final_.c_str(), path_.c_str());
  placed_ = exchanged_ = false;
}

void PartialDirectory::drop_earlier() {
  committed_ = true;
  if (!exchanged_) return;
  std::error_code ec;
  fs::remove_all(path_, ec);  // the earlier folder, swapped here
  if (ec)
    throw failure("the new " + options_.what + " is complete in " + final_ + ", but the old one, moved to " + path_ +
                  ", could not be removed: " + ec.message());
}

}  // namespace haptex
