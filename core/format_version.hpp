#pragma once
// Format names are FAMILY/VERSION ("dataset/4", "split/1": docs/architecture.md, "Formats"), in HDF5
// root attributes and JSON "format" fields alike. A file of a later version than this haptex reads
// came from a newer haptex, and is refused saying so, whatever kind of file it is.
#include <string>
#include <string_view>

#include "core/error.hpp"

namespace haptex {

// True when `name` is FAMILY/N with N a version haptex writes: 1, 2, ... in plain decimal ("recordings/01",
// "recordings/-1" and "recordings/ 1" are not: review 15, R2).
bool is_format_name(std::string_view name);
// True when `found` names wanted's family with a higher version ("split/2" for "split/1").
bool is_newer_version(std::string_view found, std::string_view wanted);
// The refusal (bad_input) for such a file: "FILE: WHERE: is split/2, written by a newer haptex ...".
[[nodiscard]] Error newer_version_error(const std::string& file, const std::string& where, const std::string& found,
                                        const std::string& wanted);

// For --force on an existing output `path` whose format is `found` (nothing: not a file haptex wrote)
// when the command writes `wanted`: haptex replaces only an earlier output of the same kind, so this
// throws haptex::Error (bad_input) naming path when `found` is missing, of another family ("is a
// recordings/2 file"), or of a later version (written by a newer haptex).
// `written_by`: the haptex version the file states (HDF5 `haptex_version`, JSON "haptex_version"; empty
// when it states none); one newer than this haptex's, or one no haptex writes, is refused too,
// whatever its format (review 10, C5; review 11, F4).
void require_replaceable_format(const std::string& path, const std::string& found, const std::string& wanted,
                                const std::string& written_by = "");
// True when `version` ("1.2.3") is later than this haptex's (kVersion); false when it is no such version.
bool is_newer_haptex(std::string_view version);
// Whether `version` is a version haptex writes: decimal numbers between dots ("0.1.0"), nothing else.
bool is_haptex_version(std::string_view version);

}  // namespace haptex
