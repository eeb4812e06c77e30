#pragma once
// Good files from the real pipeline, made once per test program: haptex synth materials (2
// materials, 5 presses, 3 s recordings, 160 x 120 frames), convert, capture extract, align and split.
// Tests copy a file, break one thing in the copy, and expect exactly the matching check to fail.
#include <set>
#include <string>

#include "qa/report.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {

struct QaFiles {
  std::string recordings, gelsight, dataset, split;
};

// Builds the files on first use (each step through the haptex binary, as a user runs it).
const QaFiles& qa_files();

// A copy of `file` in a fresh folder owned by `dir`, named `name`.
std::string copy_into(const TempDir& dir, const std::string& file, const std::string& name);

// The ids of the checks that failed.
std::set<std::string> failed_ids(const qa::Report& report);
std::string describe(const qa::Report& report);  // every failed check with its message, for test output

}  // namespace haptex::test

namespace haptex::test {

// Expects exactly one failed check, `id` (and prints every failure otherwise).
void expect_only(const qa::Report& report, const std::string& id);

}  // namespace haptex::test
