#pragma once
// An HDF5 file written as NAME.partial and renamed on commit() (core/durable_file.hpp): until then
// the final name is untouched, and an AtomicFile destroyed without commit() removes its partial
// file, so an error never leaves a half-written output behind.
#include <string>

#include "core/durable_file.hpp"
#include "core/h5/file.hpp"

namespace haptex::h5 {

class AtomicFile {
 public:
  // Refuses (haptex::Error, bad_input) when final_path exists and overwrite is false, when its
  // directory does not exist or is not writable, or when another run is writing it.
  AtomicFile(std::string final_path, bool overwrite);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  Group root() const { return file_.root(); }
  File& file() { return file_; }
  const std::string& final_path() const { return final_path_; }
  const std::string& partial_path() const { return partial_.path(); }
  // Flushes and closes the file (every group and dataset handle of it is invalid afterwards),
  // then syncs and renames it.
  void commit();

 private:
  std::string final_path_;
  PartialFile partial_;
  File file_;
};

}  // namespace haptex::h5
