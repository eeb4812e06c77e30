#pragma once
// Runs the built haptex binary (or python3 for the numpy and h5py checks) as a user would, from an
// argv and never through a shell, capturing exit code, stdout and stderr.
#include <string>
#include <vector>

namespace haptex::test {

struct CommandResult {
  int exit_code = -1;
  std::string out, err;
};

// The haptex binary the tests run: this build's, or the one HAPTEX_TEST_BINARY names (to run the
// end-to-end tests against another build, e.g. the previous release, and see which fail there).
std::string haptex_binary();

CommandResult run_haptex(const std::vector<std::string>& args);
// The same with `directory` as the working directory (relative paths in args are relative to it).
CommandResult run_haptex_in(const std::string& directory, const std::vector<std::string>& args);
// The same with standard input read from the file `input`.
CommandResult run_haptex_fed(const std::vector<std::string>& args, const std::string& input);
// Runs any program with its arguments (in `directory` when given); exit code 127 when it is missing.
CommandResult run_program(const std::vector<std::string>& argv, const std::string& directory = "");
// /usr/bin/python3 with these arguments (a script and its arguments, or -c CODE and its arguments).
CommandResult run_python(const std::vector<std::string>& args);
// Whether /usr/bin/python3 can import these modules ("h5py, numpy").
bool python_has(const std::string& modules);
// Whether stderr holds only progress as a command logs it where stderr is no terminal (apps/
// terminal_progress.hpp): whole lines "LABEL: DONE/TOTAL WHAT (N s)", no bar redrawn in place.
bool only_progress_lines(const std::string& err);
// stderr without those lines: what a command said besides its progress.
std::string without_progress_lines(const std::string& err);

}  // namespace haptex::test
