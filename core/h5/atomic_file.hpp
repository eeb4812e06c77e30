#pragma once
// An HDF5 file written as NAME.partial and renamed on commit() (core/durable_file.hpp): until then
// the final name is untouched, and an AtomicFile destroyed without commit() removes its partial
// file, so an error never leaves a half-written output behind.
#include <string>

#include "core/durable_file.hpp"
#include "core/h5/file.hpp"

namespace haptex::h5 {

// For --force: refuses (haptex::Error, bad_input) to replace an existing file at path unless haptex
// wrote it as an earlier output of `format`'s kind (core/format_version.hpp,
// require_replaceable_format): a user's own file, another kind of haptex file and a newer haptex's
// are never overwritten. A path that does not exist, or is not a regular file (core/durable_file.hpp
// refuses that), passes.
void require_replaceable(const std::string& path, const std::string& format);

class AtomicFile : public StagedOutput {
 public:
  // Refuses (haptex::Error, bad_input) when final_path exists and overwrite is false, or exists and
  // is not an earlier file of `format` (the haptex_format the caller will stamp: --force replaces only
  // those, require_replaceable), when its directory does not exist or is not writable, or when
  // another run is writing it. `format` may be left out only without overwrite.
  AtomicFile(std::string final_path, bool overwrite, const std::string& format = {});
  ~AtomicFile() override;
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  Group root() const { return file_.root(); }
  File& file() { return file_; }
  const std::string& final_path() const { return final_path_; }
  const std::string& partial_path() const { return partial_.path(); }
  // Flushes, closes (every group and dataset handle of the file is invalid afterwards) and syncs
  // the file, without renaming it: outputs that appear together finish all before renaming any.
  void finish() override;
  // finish() when not done, then renames the file to its final name (commit_together({this})).
  void commit();

  // core/output_set.hpp; check_place also refuses an earlier file that is no longer one of `format`.
  void check_place() const override;
  void put_in_place() override { partial_.put_in_place(); }
  void take_back() noexcept override { partial_.take_back(); }
  void drop_earlier() override { partial_.drop_earlier(); }

 private:
  std::string final_path_, format_;
  PartialFile partial_;
  File file_;
};

}  // namespace haptex::h5
