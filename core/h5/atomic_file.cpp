#include "core/h5/atomic_file.hpp"

#include <filesystem>

#include "core/error.hpp"
#include "core/format_version.hpp"

namespace haptex::h5 {

void require_replaceable(const std::string& path, const std::string& format) {
  if (format.empty()) throw failure("internal: --force on " + path + " without the format to be written");
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return;
  std::string found, written_by;
  try {
    const Group root = File::open(path).root();
    if (root.has_attr(kFormatAttribute)) found = root.attr_string(kFormatAttribute);
    if (root.has_attr(kVersionAttribute)) written_by = root.attr_string(kVersionAttribute);
  } catch (const Error&) {  // not HDF5, or a format that is not text: not a file haptex wrote
  }
  require_replaceable_format(path, found, format, written_by);
}

namespace {

// The checks before anything is written, in the order a user fixes them.
const std::string& checked(const std::string& final_path, bool overwrite, const std::string& format) {
  check_output_path(final_path, overwrite);
  if (overwrite) require_replaceable(final_path, format);
  return final_path;
}

}  // namespace

AtomicFile::AtomicFile(std::string final_path, bool overwrite, const std::string& format)
    : final_path_((checked(final_path, overwrite, format), std::move(final_path))),
      format_(format),
      partial_(final_path_, overwrite),
      file_(partial_.open_by_name([&](const std::string& path) { return File::create(path, final_path_); })) {}

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

void AtomicFile::commit() { commit_together({this}); }

void AtomicFile::check_place() const {
  partial_.check_place();
  if (!format_.empty()) require_replaceable(final_path_, format_);
}

}  // namespace haptex::h5
