#include "tests/support/run_haptex.hpp"

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <iterator>

#include "tests/support/temp_dir.hpp"

namespace haptex::test {

std::string shell_quote(const std::string& word) {
  std::string quoted = "'";
  for (char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

static std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

CommandResult run_shell(const std::string& command_line) {
  TempDir dir;
  const std::string out = dir.file("out"), err = dir.file("err");
  const int status = std::system((command_line + " > " + shell_quote(out) + " 2> " + shell_quote(err) + " < /dev/null").c_str());
  CommandResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = slurp(out);
  result.err = slurp(err);
  return result;
}

CommandResult run_haptex(const std::vector<std::string>& args) {
  std::string command = shell_quote(HAPTEX_BINARY);
  for (const auto& arg : args) command += " " + shell_quote(arg);
  return run_shell(command);
}

}  // namespace haptex::test
