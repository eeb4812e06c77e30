#pragma once
// Starting another program (gnuplot, python3 in the tests) the one safe way: an argv handed to
// posix_spawnp, never a command line for a shell, so no file name or label can become a command.
#include <string>
#include <vector>

namespace haptex::process {

struct ProgramRun {
  std::vector<std::string> argv;  // argv[0] is looked up on PATH when it has no '/'
  std::string directory;          // working directory of the child; empty: this process's
  std::string stdout_path;        // where its standard output goes; empty: /dev/null
  std::string stderr_path;        // where its standard error goes; empty: /dev/null
  std::string stdin_path;         // what its standard input reads; empty: /dev/null
  std::vector<std::string> environment;  // NAME=value set for it, beside (or over) this process's own
};

// The exit code of a program that could not be started (not installed, not executable, no descriptor
// or memory left to start it; errno says which): the shell's convention for "command not found".
inline constexpr int kNotStarted = 127;

// Runs the program to its end and returns its exit code:
// kNotStarted when it could not be started, 128 + N when signal N ended it.
int run_program(const ProgramRun& run);

// run_program, its standard output read through a pipe instead (stdout_path is not used): the last
// `most` bytes of it in `tail`, the rest read and dropped so the program never waits on a full pipe.
// `descriptor`, when one (>= 0), is given to the program as its descriptor 3 (kPassedDescriptor).
int run_program_reading(const ProgramRun& run, std::string& tail, std::size_t most, int descriptor = -1);
inline constexpr int kPassedDescriptor = 3;

// Whether name is an executable file in one of PATH's folders (or, with a '/', at that path).
bool program_on_path(const std::string& name);

}  // namespace haptex::process
