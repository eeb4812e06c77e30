#pragma once
// JSON documents checked against the JSON Schemas in schemas/ (compiled in), with valijson.
#include <nlohmann/json_fwd.hpp>

#include <string>
#include <string_view>

#include "core/durable_file.hpp"

namespace haptex::json {

// Parses a JSON file; a syntax error becomes haptex::Error (bad_input) naming the file and byte.
nlohmann::json read_file(const std::string& path);

// Whether path is a JSON file (of at most 64 MiB) whose top-level "format" is `format`: how --force
// knows that haptex wrote it. Never throws.
bool has_format(const std::string& path, std::string_view format);

// Throws haptex::Error (bad_input) naming `file`, the JSON pointer of the first failing element and
// the reason, when doc does not satisfy schemas/<schema_name>.
void validate(const nlohmann::json& doc, std::string_view schema_name, const std::string& file);

// Validates doc against schemas/<schema_name> (a failure there is a bug: Kind::failed), then writes
// it indented, atomically (a temporary name, fsync, rename), as a new file: one at path is never replaced.
void write_file(const nlohmann::json& doc, std::string_view schema_name, const std::string& path);
// The same into out's temporary file, not committed: for a command whose outputs appear together.
void write_file(const nlohmann::json& doc, std::string_view schema_name, PartialFile& out);

}  // namespace haptex::json
