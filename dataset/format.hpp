#pragma once
// The files haptex writes, by format: the root attribute haptex_format names the kind and its
// version ("dataset/4"), and every reader opens a file through open_checked, so a file of another
// kind or an older version is refused in one place, with the file and the fix
// (schemas/hdf5-layout.md; docs/architecture.md, "Formats").
#include <span>
#include <string>
#include <string_view>

#include "core/h5/file.hpp"

namespace haptex::dataset {

enum class Kind { recordings, gelsight, dataset, model, truth, press, windows };

struct Format {
  Kind kind;
  std::string_view family;      // "dataset"
  int version;                  // the version this haptex writes and reads
  std::string_view written_by;  // "haptex align"
  std::string_view older;       // why an older version is refused ("" when there was none)
};

const Format& format_of(Kind kind);
// Every HDF5 format this haptex writes; docs/architecture.md's table lists each (tests/dataset/format_table_test.cpp).
std::span<const Format> formats();
std::string format_name(Kind kind);  // "dataset/4"
// "recordings/1, gelsight/2 or dataset/4": the current formats of `kinds`, for messages.
std::string format_list(std::span<const Kind> kinds, std::string_view last_joint = " or ");

// Why this haptex cannot read a file whose /@haptex_format is `found`, for `haptex info`, which shows
// any file: "" when `found` is a format this haptex reads; else "written by a newer haptex: this one
// reads dataset/4", "an older version: this haptex reads dataset/4, which haptex align writes", "no
// version haptex writes: the attribute was edited or damaged" or "no kind of file haptex writes".
std::string format_remark(std::string_view found);

// The file's /@haptex_format. Throws haptex::Error (bad_input) naming the file when the attribute
// is missing (not a haptex file), not a string or not UTF-8.
std::string read_format(const h5::File& file);
// The same attribute's bytes as stored, UTF-8 or not: for showing a file haptex cannot read (info).
std::string read_format_bytes(const h5::File& file);

// Opens path and checks it is a file of `kind` in the current version whose every object keeps the
// link rule (core/h5/link_rule.hpp). Throws haptex::Error (bad_input) naming the file and
// /@haptex_format: not HDF5, not a haptex file, another kind, or an older version (saying what
// changed and which command writes the current one); or the first object that breaks the rule.
h5::File open_checked(const std::string& path, Kind kind);

struct OpenedFile {
  h5::File file;
  Kind kind;
};
// Opens path as a file of any of `kinds` (the one its family names), through open_checked, so an
// older or newer version is refused as every reader refuses it. A file of another kind is refused
// (bad_input) as "is 'model/3': <who> recordings/1, gelsight/2 or dataset/4 files. <fix>".
// Links::report leaves the link rule to the caller: qa, which reports every break (`layout.links`).
enum class Links { refuse, report };
OpenedFile open_any(const std::string& path, std::span<const Kind> kinds, const std::string& who, const std::string& fix,
                    Links links = Links::refuse);


// The root attributes every haptex file carries (core/h5/file.hpp, stamp_root) for `kind`.
void stamp(h5::Group root, Kind kind, const std::string& source);

}  // namespace haptex::dataset
