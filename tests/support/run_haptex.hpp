#pragma once
// Runs the built haptex binary as a user would, capturing exit code, stdout and stderr.
#include <string>
#include <vector>

namespace haptex::test {

struct CommandResult {
  int exit_code = -1;
  std::string out, err;
};

CommandResult run_haptex(const std::vector<std::string>& args);
// Runs any shell command line (used for python3 checks); exit code 127 when the program is missing.
CommandResult run_shell(const std::string& command_line);
std::string shell_quote(const std::string& word);

}  // namespace haptex::test
