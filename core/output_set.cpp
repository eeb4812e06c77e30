#include "core/output_set.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <vector>

#include "core/error.hpp"
#include "core/temporary_name.hpp"

namespace haptex {
namespace fs = std::filesystem;

void EarlierOutput::require_retirable(const std::string& path, const std::function<bool(const std::string& path)>& retire,
                                      const std::string& what, const std::string& fix) {
  std::error_code ec;
  const fs::file_status status = fs::symlink_status(path, ec);
  if (!fs::exists(status) || retire(path)) return;
  if (fs::is_symlink(status))
    throw input_error(path, "", "is " + what + " of the output --force replaces, and a symbolic link, which haptex never replaces",
                      "Remove the link, or name the output elsewhere");
  throw input_error(path, "", "is " + what + " of the output --force replaces, and holds what haptex did not write: it would stay "
                                  "beside a new output it no longer describes",
                    fix);
}

EarlierOutput::EarlierOutput(std::string path, std::function<bool(const std::string& path)> retire)
    : path_(std::move(path)), retire_(std::move(retire)) {}

EarlierOutput::~EarlierOutput() {
  if (aside_.empty()) return;
  std::error_code ec;
  if (!moved_) fs::remove(aside_, ec);  // the fresh temporary, empty (or gone with what was moved onto it)
  forget_temporary(aside_);
  ::close(fd_);
}

void EarlierOutput::finish() {
  // Outside hold_temporaries (commit_together), which no temporary may be made under: a fresh one of
  // the earlier output's kind (an empty folder or file a rename may replace) to move it onto.
  std::error_code ec;
  const fs::file_status status = fs::symlink_status(path_, ec);
  if (!fs::exists(status) || !retire_(path_) || !aside_.empty()) return;
  Temporary aside = fs::is_directory(status) ? create_temporary_folder(path_) : create_temporary_file(path_);
  aside_ = aside.path;
  fd_ = aside.fd;
}

void EarlierOutput::check_place() const {
  std::error_code ec;
  retiring_ = !aside_.empty() && fs::exists(fs::symlink_status(path_, ec)) && retire_(path_);
}

void EarlierOutput::put_in_place() {
  if (!retiring_) return;
  if (std::rename(path_.c_str(), aside_.c_str()) != 0)
    throw failure(path_ + ": cannot move the earlier output aside to replace it: " + std::strerror(errno));
  moved_ = true;
}

void EarlierOutput::take_back() noexcept {
  // When something took its name meanwhile, the earlier output stays at aside_ (never removed).
  if (moved_ && ::renameat2(AT_FDCWD, aside_.c_str(), AT_FDCWD, path_.c_str(), RENAME_NOREPLACE) == 0) moved_ = false;
}

void EarlierOutput::drop_earlier() {
  if (!moved_) return;
  std::error_code ec;
  fs::remove_all(aside_, ec);
  moved_ = false;
}

void commit_together(const std::vector<StagedOutput*>& outputs) {
  std::vector<StagedOutput*> members;
  for (StagedOutput* output : outputs)
    if (output) members.push_back(output);
  for (StagedOutput* output : members) output->finish();
  const auto together = hold_temporaries();
  for (StagedOutput* output : members) output->check_place();
  std::size_t placing = 0;
  try {
    for (; placing < members.size(); ++placing) members[placing]->put_in_place();
  } catch (...) {
    // The one that failed too: take_back undoes whatever of its rename was done, and nothing else.
    for (std::size_t k = placing + 1; k-- > 0;) members[k]->take_back();
    throw;
  }
  for (StagedOutput* output : members) output->drop_earlier();
}

std::string relative_to_folder_of(const std::string& path, const std::string& file) {
  return fs::absolute(path).lexically_relative(fs::absolute(file).parent_path()).string();
}

std::string resolved_beside(const std::string& recorded, const std::string& file) {
  return (fs::path(file).parent_path() / recorded).lexically_normal().string();
}

}  // namespace haptex
