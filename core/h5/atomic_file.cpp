#include "core/h5/atomic_file.hpp"

#include <filesystem>

#include "core/error.hpp"

namespace haptex::h5 {

void require_replaceable(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return;
  std::string why = "it has no haptex_format attribute";
  try {
    if (File::open(path).root().has_attr(kFormatAttribute)) return;
  } catch (const Error&) {
    why = "it is not an HDF5 file haptex can read";
  }
  throw input_error(path, "", "--force replaces only a file haptex wrote, and " + why,
                    "Choose another output name, or move the file away yourself");
}

namespace {

// The checks before anything is written, in the order a user fixes them.
const std::string& checked(const std::string& final_path, bool overwrite) {
  check_output_path(final_path, overwrite);
  if (overwrite) require_replaceable(final_path);
  return final_path;
}

}  // namespace

AtomicFile::AtomicFile(std::string final_path, bool overwrite)
    : final_path_((checked(final_path, overwrite), std::move(final_path))),
      partial_(final_path_, overwrite),
      file_(File::create(partial_.path(), final_path_)) {}

AtomicFile::~AtomicFile() {
  try {
    file_.close();
  } catch (...) {  // the file is abandoned; PartialFile removes it
  }
}

void AtomicFile::finish() {
  if (file_.is_open()) {
    file_.flush();
    file_.close();
  }
  partial_.finish();
}

void AtomicFile::commit() {
  finish();
  partial_.commit();
}

}  // namespace haptex::h5
