#include "core/h5/file.hpp"

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>

#include "core/error.hpp"
#include "core/h5/structure_probe.hpp"
#include "core/input_file.hpp"
#include "core/open_files.hpp"
#include "core/version.hpp"

namespace haptex::h5 {

File File::open(const std::string& path, bool writable) {
  silence_library_errors();
  require_regular_file(path);
  const htri_t hdf5 = H5Fis_hdf5(path.c_str());
  // H5Fis_hdf5 answers 0 for a file that is not HDF5 and fails (< 0) for one it cannot open: out of
  // descriptors is the machine's limit (core/open_files.hpp), anything else is said as what it is.
  if (const int error = hdf5 < 0 ? error_opening(path) : 0; error != 0)
    throw input_error(path, "", std::string("cannot open it (") + std::strerror(error) + ")", "Check the file's permissions");
  if (hdf5 <= 0)
    throw input_error(path, "", "not an HDF5 file", "Give a file written by haptex (recordings, gelsight, dataset or model)");
  if (!writable) probe_structure(path);
  const hid_t id = H5Fopen(path.c_str(), writable ? H5F_ACC_RDWR : H5F_ACC_RDONLY, H5P_DEFAULT);
  // HDF5 locks a file another program writes (an h5py session, a running haptex): the file is whole,
  // and "copy it again" would mislead (review 15, R8).
  if (id < 0) {
    const std::string detail = last_library_error();
    if (detail.find("Resource temporarily unavailable") != std::string::npos || detail.find("unable to lock file") != std::string::npos)
      throw input_error(path, "", "another program has it open for writing (HDF5's file lock: " + detail + ")",
                        "Close it there (an h5py session, a haptex run) and run again; on a file system whose locks do not "
                        "work, set HDF5_USE_FILE_LOCKING=FALSE");
    throw input_failure("open the file", path, detail);
  }
  Handle file(id);
  if (!writable) probe_structure(id, path);
  return File(std::move(file), path);
}

File File::create(const std::string& path, const std::string& shown_as) {
  silence_library_errors();
  Handle access(H5Pcreate(H5P_FILE_ACCESS));
  // Closing the file closes every object still open in it, so close() really finishes the file.
  H5Pset_fclose_degree(access.get(), H5F_CLOSE_STRONG);
  // The caller holds the lock (PartialFile); HDF5's own lock on a second descriptor would clash with it.
  H5Pset_file_locking(access.get(), false, true);
  const std::string& named = shown_as.empty() ? path : shown_as;
  Handle file(check(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get()), "create the file", named));
  return File(std::move(file), named);
}

bool not_hdf5(const std::string& path) {
  silence_library_errors();
  return H5Fis_hdf5(path.c_str()) == 0;
}

Group File::root() const {
  return Group(Handle(check_input(H5Gopen2(handle_.get(), "/", H5P_DEFAULT), "open the root group", path_)), path_, "/");
}

void File::flush() { check_status(H5Fflush(handle_.get(), H5F_SCOPE_GLOBAL), "flush the file", path_); }

void File::close() {
  if (!handle_.valid()) return;
  check_status(H5Fclose(handle_.release()), "close the file", path_);
}

std::string utc_now_iso8601() {
  std::time_t now = std::time(nullptr);
  if (const char* epoch = std::getenv("SOURCE_DATE_EPOCH")) now = static_cast<std::time_t>(std::atoll(epoch));
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

void stamp_root(Group root, const std::string& format, const std::string& source) {
  root.set_attr(kFormatAttribute, format);
  root.set_attr(kVersionAttribute, kVersion);
  root.set_attr(kCreatedAttribute, utc_now_iso8601());
  root.set_attr(kSourceAttribute, source);
}

}  // namespace haptex::h5
