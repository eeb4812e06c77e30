#pragma once
// An HDF5 file opened for reading or created for writing. New files are written through
// AtomicFile (core/h5/atomic_file.hpp) so a crash never leaves a half file under the final name.
#include <array>
#include <string>

#include "core/h5/node.hpp"

namespace haptex::h5 {

class File {
 public:
  // Throws haptex::Error (bad_input) naming the path when it is missing or not an HDF5 file.
  static File open(const std::string& path, bool writable = false);
  // Creates (or truncates) a file. Messages name it `shown_as` when given (AtomicFile: the output's
  // final name, not its temporary one).
  static File create(const std::string& path, const std::string& shown_as = "");

  const std::string& path() const { return path_; }
  Group root() const;
  void flush();
  void close();  // closes every object of the file; throws when HDF5 reports a failure
  bool is_open() const { return handle_.valid(); }

 private:
  File(Handle handle, std::string path) : handle_(std::move(handle)), path_(std::move(path)) {}
  Handle handle_;
  std::string path_;
};

// Whether `path` was read and found not to be an HDF5 file (a file HDF5 cannot open at all is
// File::open's to explain).
bool not_hdf5(const std::string& path);

// Root attributes every haptex file carries (docs/architecture.md, "Formats"): haptex_format (e.g. "recordings/1"),
// haptex_version, created_utc (ISO 8601; SOURCE_DATE_EPOCH is honoured for reproducible files), source.
inline constexpr const char* kFormatAttribute = "haptex_format";
inline constexpr const char* kVersionAttribute = "haptex_version";
inline constexpr const char* kCreatedAttribute = "created_utc";
inline constexpr const char* kSourceAttribute = "source";
inline constexpr std::array<const char*, 4> kStampAttributes{kFormatAttribute, kVersionAttribute, kCreatedAttribute,
                                                            kSourceAttribute};
void stamp_root(Group root, const std::string& format, const std::string& source);
std::string utc_now_iso8601();

}  // namespace haptex::h5
