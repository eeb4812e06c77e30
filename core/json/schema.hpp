#pragma once
// JSON documents checked against the JSON Schemas in schemas/ (compiled in), with valijson.
#include <nlohmann/json_fwd.hpp>

#include <string>
#include <cstdint>
#include <string_view>

#include "core/durable_file.hpp"

namespace haptex::json {

// Parses a JSON file; a syntax error becomes haptex::Error (bad_input) naming the file and byte.
nlohmann::json read_file(const std::string& path);

// The one parser of JSON haptex did not write itself: `text` (a whole file, an attribute) as a
// document. Throws haptex::Error (bad_input) naming `file`: not JSON (the byte), a number beyond
// 64-bit floats ("1e400"), nesting deeper than kDeepestJson levels (a validator walking it would
// run out of stack; no haptex document nests past 6), or a NUL character in a key or a string (C
// strings downstream would cut it off), or a key given twice in one object (the parser would keep
// the last without a word; the error names its JSON pointer).
inline constexpr int kDeepestJson = 64;
inline constexpr std::uintmax_t kLargestJsonBytes = 64u << 20;  // read_file refuses a larger file
nlohmann::json parse_text(std::string_view text, const std::string& file);

// The checks before writing a JSON document of `format` ("split/1") at path: check_output_path, and
// with overwrite an existing file is replaced only when it is a JSON file (of at most 64 MiB) whose
// top-level "format" is an earlier `format` (require_replaceable_format, core/format_version.hpp):
// how --force knows that haptex wrote it.
void check_replaceable_json(const std::string& path, bool overwrite, const std::string& format);

// Throws haptex::Error (bad_input) naming `file`, the JSON pointer of the first failing element and
// the reason, when doc does not satisfy schemas/<schema_name>.
void validate(const nlohmann::json& doc, std::string_view schema_name, const std::string& file);

// Validates doc against schemas/<schema_name> (a failure there is a bug: Kind::failed), then writes
// it indented, atomically (a temporary name, fsync, rename), as a new file: one at path is never replaced.
void write_file(const nlohmann::json& doc, std::string_view schema_name, const std::string& path);
// The same into out's temporary file, not committed: for a command whose outputs appear together.
void write_file(const nlohmann::json& doc, std::string_view schema_name, PartialFile& out);

}  // namespace haptex::json
