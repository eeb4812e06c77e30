#include "core/h5/atomic_file.hpp"

#include <cstdio>

#include "core/durable_file.hpp"

namespace haptex::h5 {

AtomicFile::AtomicFile(std::string final_path, bool overwrite)
    : final_path_((check_output_path(final_path, overwrite), std::move(final_path))),
      partial_path_(create_partial(final_path_)),
      file_(File::create(partial_path_)) {}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  try {
    file_.close();
  } catch (...) {  // the file is abandoned anyway
  }
  std::remove(partial_path_.c_str());
}

void AtomicFile::commit() {
  file_.flush();
  file_.close();
  durable_rename(partial_path_, final_path_);
  committed_ = true;
}

}  // namespace haptex::h5
