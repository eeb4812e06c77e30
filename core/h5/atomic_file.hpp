#pragma once
// Writes NAME.partial, then on commit(): flush, close, fsync, rename to NAME, fsync the directory.
// Until commit() the final name is untouched; an AtomicFile destroyed without commit() removes
// its partial file, so an error never leaves a half-written output behind.
#include <string>

#include "core/h5/file.hpp"

namespace haptex::h5 {

class AtomicFile {
 public:
  // Refuses (haptex::Error, bad_input) when final_path exists and overwrite is false, or when its
  // directory does not exist or is not writable: checked before any work is done.
  AtomicFile(std::string final_path, bool overwrite);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  Group root() const { return file_.root(); }
  File& file() { return file_; }
  const std::string& final_path() const { return final_path_; }
  const std::string& partial_path() const { return partial_path_; }
  void commit();

 private:
  std::string final_path_;
  std::string partial_path_;
  File file_;
  bool committed_ = false;
};

}  // namespace haptex::h5
