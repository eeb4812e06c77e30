#pragma once
// Every check `haptex qa` knows: its stable id, severity, the kinds of file it runs on, what it
// measures and the one-line fix hint. docs/qa.md documents the same list (a test keeps them in step).
#include <cstdint>
#include <string_view>
#include <vector>

#include "qa/check.hpp"

namespace haptex::qa {

enum class FileKind { recordings, gelsight, dataset, split };
std::string_view to_string(FileKind kind);

struct CheckInfo {
  std::string_view id;
  Severity severity;
  std::string_view measures;  // what the check looks at, with its threshold
  std::string_view hint;      // the fix
};

const std::vector<CheckInfo>& all_checks();
// Throws haptex::Error (failed) for an id that is not in the catalog (a programming error).
const CheckInfo& check_info(std::string_view id);

}  // namespace haptex::qa
