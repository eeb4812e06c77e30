#pragma once
// An HDF5 file written as NAME.partial and renamed on commit() (core/durable_file.hpp): until then
// the final name is untouched, and an AtomicFile destroyed without commit() removes its partial
// file, so an error never leaves a half-written output behind.
#include <string>

#include "core/durable_file.hpp"
#include "core/h5/file.hpp"

namespace haptex::h5 {

// For --force: refuses (haptex::Error, bad_input) to replace an existing file at path that haptex
// did not write (not HDF5, or no haptex_format), so a user's own file is never overwritten. A path
// that does not exist, or is not a regular file (core/durable_file.hpp refuses that), passes.
void require_replaceable(const std::string& path);

class AtomicFile {
 public:
  // Refuses (haptex::Error, bad_input) when final_path exists and overwrite is false, or exists and
  // is not a file haptex wrote (--force replaces only those: require_replaceable), when its
  // directory does not exist or is not writable, or when another run is writing it.
  AtomicFile(std::string final_path, bool overwrite);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  Group root() const { return file_.root(); }
  File& file() { return file_; }
  const std::string& final_path() const { return final_path_; }
  const std::string& partial_path() const { return partial_.path(); }
  // Flushes, closes (every group and dataset handle of the file is invalid afterwards) and syncs
  // the file, without renaming it: outputs that appear together finish all before renaming any.
  void finish();
  // finish() when not done, then renames the file to its final name.
  void commit();

 private:
  std::string final_path_;
  PartialFile partial_;
  File file_;
};

}  // namespace haptex::h5
