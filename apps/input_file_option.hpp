#pragma once
// Input files named on the command line are checked by haptex's own rule (core/input_file.hpp), as
// every reader checks its files: a missing file, a dangling link, a folder, a FIFO or device get the
// message that names the file and the fix, and --json's "file" (review 15, R1). CLI11's ExistingFile
// answered before it, in its own words and without them.
#include <CLI/CLI.hpp>

namespace haptex::apps {

// Marks an option as an input file (its help shows FILE, as ExistingFile's did); the check runs with
// the other option checks before any work (run_main.cpp).
CLI::Validator input_file();
// Whether `option` carries that mark.
bool is_input_file_option(const CLI::Option& option);

}  // namespace haptex::apps
