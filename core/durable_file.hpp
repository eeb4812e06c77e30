#pragma once
// The file-system half of haptex's atomic writes (docs/architecture.md, "Outputs are atomic"): every
// output is written to a temporary name beside it (core/temporary_name.hpp), synced, and renamed, so a
// crash never leaves a half file under the final name.
#include <functional>
#include <string>
#include <string_view>

#include "core/output_set.hpp"
#include "core/temporary_name.hpp"

namespace haptex {

// Checks that path can be created: its directory exists and is writable, and it does not exist
// (or, with overwrite, is a regular file). Throws haptex::Error (bad_input) saying which and what to do.
void check_output_path(const std::string& path, bool overwrite);
// For --force on an output that is not HDF5: check_output_path's checks, then a refusal (bad_input)
// to replace an existing file unless haptex_wrote(path) tells that haptex wrote it (by the mark each
// format carries: docs/architecture.md, "Outputs are atomic"); `what` names such a file ("a WAV haptex
// rendered") in the message.
void check_replaceable_output(const std::string& path, bool overwrite, const std::string& what,
                              bool (*haptex_wrote)(const std::string& path));
// Why a write failed, as a user reads it: "the disk is full" for ENOSPC and EDQUOT (a quota is a
// full disk to the user), else strerror(error).
std::string why_not_written(int error);
// fsync one file or (with O_DIRECTORY in flags) directory; throws haptex::Error (failed) naming it.
void fsync_path(const std::string& path, int flags);

// A folder opened to be synced after a rename into it. Opened before the rename, so that a run out of
// file descriptors fails before its output is in place, not after it (review 25, F2: exit 1 with the
// output whole under its final name).
class DirectoryToSync {
 public:
  explicit DirectoryToSync(const std::string& path);  // throws haptex::Error (failed)
  ~DirectoryToSync();
  DirectoryToSync(const DirectoryToSync&) = delete;
  DirectoryToSync& operator=(const DirectoryToSync&) = delete;
  void sync() const;  // throws haptex::Error (failed): the disk is full or failing

 private:
  std::string path_;
  int fd_;
};
// Rename `from` (already synced by the caller) to `to`, then fsync the directory. Without `replace`, a `to` that exists by then
// (it appeared while the run wrote: a user's file, another run's output) is kept and refused
// (bad_input), atomically (RENAME_NOREPLACE).
void durable_rename(const std::string& from, const std::string& to, bool replace);

// A new temporary file for NAME (core/temporary_name.hpp), locked (flock) for as long as this object
// lives, so two haptex runs writing the same output refuse instead of corrupting each other.
class PartialFile : public StagedOutput {
 public:
  // Throws bad_input: unwritable, or locked by another run. `replace`: --force was given, so a file at
  // the final name (checked as haptex's before the work) is replaced; without it nothing that exists
  // there when the file is renamed is ever replaced. `still_replaceable`, with replace, checks that
  // file again just before the swap (check_replaceable_output, json::check_replaceable_json), so one
  // of the user's that took its place meanwhile is kept.
  using ReplaceableCheck = std::function<void(const std::string& final_path)>;
  PartialFile(const std::string& final_path, bool replace, ReplaceableCheck still_replaceable = {});
  ~PartialFile() override;                               // removes the file unless kept
  PartialFile(const PartialFile&) = delete;
  PartialFile& operator=(const PartialFile&) = delete;

  const std::string& path() const { return path_; }
  const std::string& final_path() const { return final_path_; }
  // open(path()), for a library that opens the temporary by name (HDF5, libsndfile), run while the
  // temporaries are held (hold_temporaries): a Ctrl-C then removes the file either before (and the
  // run ends without opening it) or after the library holds it open, never in between, where the
  // library would make it anew under the name and leave it behind.
  // The name given is the descriptor's own (core/temporary_name.hpp, name_of_descriptor): a link or a
  // file put at the temporary name meanwhile is never what the library opens (review 14, F1).
  template <class Open>
  auto open_by_name(Open&& open) const {
    const auto held = hold_temporaries();
    try {
      return open(name_of_descriptor(fd_, path_));
    } catch (...) {
      require_not_swapped();  // the library's failure to open it, said as what it is
      throw;
    }
  }
  // fsync (failed: a full disk), without renaming: outputs that appear together finish every one of
  // them before the first is renamed (core/output_set.hpp).
  void finish() override;
  // Alone: commit_together({this}): rename to the final path, fsync the directory; afterwards nothing is removed.
  void commit();

  // core/output_set.hpp. Without `replace`, a file at the final name refuses the output (it appeared
  // while the run wrote). A file system without RENAME_EXCHANGE replaces an earlier file at once,
  // and take_back then leaves the new one in place.
  void check_place() const override;
  void put_in_place() override;
  void take_back() noexcept override;
  void drop_earlier() override;

 private:
  friend void write_text(PartialFile& out, std::string_view text);
  void rename_into_place();
  void require_not_swapped() const;
  std::string final_path_, path_;
  int fd_ = -1;
  ReplaceableCheck still_replaceable_;
  bool replace_ = false, finished_ = false, committed_ = false;
  // Renamed; swapped with an earlier file, now at path_; or replaced it at once (no RENAME_EXCHANGE).
  bool placed_ = false, exchanged_ = false, replaced_ = false;
};

// The whole of `bytes` as a new file at path (created exclusively, O_EXCL | O_NOFOLLOW), for a file
// inside a folder being built (core/partial_directory.hpp syncs and renames it with the folder). Throws haptex::Error
// (failed) naming path and why_not_written when a write fails.
void write_whole_file(const std::string& path, std::string_view bytes);

// The whole of `text` into out's temporary file, through the descriptor it was created with (the
// commit is the caller's: several outputs can appear together). Throws haptex::Error (failed) naming the output when writing fails (a full disk).
void write_text(PartialFile& out, std::string_view text);

// The whole of `text` as a new file at path, through PartialFile: the final name appears only once
// everything is written and synced. Throws haptex::Error (failed) naming the file when writing fails.
void write_file_durably(const std::string& path, std::string_view text, bool replace,
                        PartialFile::ReplaceableCheck still_replaceable = {});

}  // namespace haptex
