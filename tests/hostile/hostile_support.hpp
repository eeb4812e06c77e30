#pragma once
// What every hostile-input test asserts about a refused command (issue 11): exit code 2, one message
// naming the file, and nothing written: no output, no NAME.partial.
#include <string>
#include <vector>

#include "tests/support/run_haptex.hpp"

namespace haptex::test {

// Adds a gtest failure unless r exited with `code` and its stderr holds every one of `mentions`.
void expect_refusal(const CommandResult& r, const std::vector<std::string>& mentions, int code = 2);

// Every path under folder whose file name is one of names (to see whether a command ran).
std::vector<std::string> files_named(const std::string& folder, const std::vector<std::string>& names);

// Every leftover NAME.partial under folder.
std::vector<std::string> partial_files(const std::string& folder);

// The file's bytes (empty when it cannot be read).
std::string file_bytes(const std::string& path);

// Starts haptex with `args` in a child process, its stdout and stderr sent to the files named, with
// `ignored` (a signal number, or 0) ignored as nohup would; returns the child's pid to signal and wait for.
int start_haptex(const std::vector<std::string>& args, const std::string& stdout_path = "/dev/null",
                 const std::string& stderr_path = "/dev/null", int ignored = 0);
// Waits for the child and returns its wait status.
int wait_for(int pid);

}  // namespace haptex::test
