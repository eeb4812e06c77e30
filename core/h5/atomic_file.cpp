#include "core/h5/atomic_file.hpp"

namespace haptex::h5 {

AtomicFile::AtomicFile(std::string final_path, bool overwrite)
    : final_path_((check_output_path(final_path, overwrite), std::move(final_path))),
      partial_(final_path_),
      file_(File::create(partial_.path())) {}

AtomicFile::~AtomicFile() {
  try {
    file_.close();
  } catch (...) {  // the file is abandoned; PartialFile removes it
  }
}

void AtomicFile::commit() {
  file_.flush();
  file_.close();
  partial_.commit();
}

}  // namespace haptex::h5
