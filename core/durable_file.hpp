#pragma once
// The file-system half of haptex's atomic writes (DESIGN.md section 5): every output is written
// to NAME.partial, synced, and renamed, so a crash never leaves a half file under the final name.
#include <string>

namespace haptex {

// Checks that path can be created: its directory exists and is writable, and it does not exist
// unless overwrite. Throws haptex::Error (bad_input) saying which and what to do.
void check_output_path(const std::string& path, bool overwrite);
// fsync `from`, rename it to `to`, fsync the directory.
void durable_rename(const std::string& from, const std::string& to);
// Creates (truncates) `path` + ".partial" and returns its name; errors name errno's reason.
std::string create_partial(const std::string& final_path);

}  // namespace haptex
