#pragma once
// Output folders haptex writes whole (synth's output, extract's contact sheets, evaluate's report),
// with the guarantees of an atomic file (core/durable_file.hpp) for a folder:
// - everything is written into a new temporary folder beside DIR (core/temporary_name.hpp), locked
//   (flock) while this object lives, so two runs writing the same folder refuse instead of mixing
//   their files;
// - commit() lists the files (core/owned_folder.hpp), fsyncs every file and folder, and renames
//   the temporary folder to DIR; an existing DIR (with overwrite) is swapped out in one rename
//   (RENAME_EXCHANGE) and only then removed, so a crash at any moment leaves the old folder or the
//   new one under DIR, never neither and never a mixture;
// - without commit() (an error, an exception) the temporary folder is removed and DIR is untouched.
// A DIR that holds anything its haptex-files.json does not list is never replaced.
#include <functional>
#include <string>

#include "core/output_set.hpp"

namespace haptex {

struct FolderOptions {
  bool overwrite = false;                 // --force: replace an earlier folder haptex wrote
  std::string what = "output folder";     // how messages name it: "report folder", "contact sheet folder"
  std::string option = "-o";              // the option that names it, for the fixes messages suggest
  std::string written_by = "haptex";      // the command, recorded in haptex-files.json
};

// The checks PartialDirectory's constructor makes before it creates anything, for a command that
// makes its folder only at the end: it refuses a folder it could not write before any work (review 14, F3).
void check_folder_destination(const std::string& dir, const FolderOptions& options);

class PartialDirectory : public StagedOutput {
 public:
  // Throws haptex::Error (bad_input) naming the folder: no usable name, its parent missing or not
  // writable, a file in its place, an existing non-empty folder without overwrite, a folder with
  // files haptex did not write, or another run writing it now.
  PartialDirectory(std::string final_path, FolderOptions options);
  ~PartialDirectory() override;
  PartialDirectory(const PartialDirectory&) = delete;
  PartialDirectory& operator=(const PartialDirectory&) = delete;

  const std::string& path() const { return path_; }         // where to write until commit()
  const std::string& final_path() const { return final_; }  // where it will be
  // Runs `write` on path() to put the folder's files there. A haptex::Error it throws is rethrown
  // naming DIR, not the temporary folder: the user asked for DIR ("REPORT/report.md: cannot write
  // it: the disk is full").
  void fill(const std::function<void(const std::string& dir)>& write) const;
  // The output the folder belongs to, which its haptex-files.json then names (write_file_list).
  void belongs_to(const std::string& output);
  // Lists the files and syncs them all (failed: a full disk), without renaming: outputs that appear
  // together finish every one of them before the first is renamed. commit() finishes when not done.
  void finish() override;
  // Alone: commit_together({this}). Throws haptex::Error (bad_input) when DIR changed meanwhile so
  // that it may no longer be replaced, (failed) when a sync or the rename fails.
  void commit();

  // core/output_set.hpp: an earlier DIR is swapped out (RENAME_EXCHANGE) and removed by drop_earlier.
  void check_place() const override;
  void put_in_place() override;
  void take_back() noexcept override;
  void drop_earlier() override;

 private:
  std::string final_, path_, owner_;
  FolderOptions options_;
  int fd_ = -1;
  bool finished_ = false, committed_ = false;
  bool placed_ = false, exchanged_ = false;  // renamed; swapped with an earlier folder, now at path_
};

}  // namespace haptex
