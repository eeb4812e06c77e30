// core/process/run_program.hpp: a program's standard output read through a pipe (haptex-h5-probe's
// answer, core/h5/structure_probe.cpp), its end kept, the rest drained so the program never blocks.
#include <gtest/gtest.h>

#include "core/process/run_program.hpp"

namespace haptex::process {
namespace {

ProgramRun program(std::vector<std::string> argv) {
  ProgramRun run;
  run.argv = std::move(argv);
  return run;
}

TEST(RunProgramReading, KeepsTheLastBytesOfALongOutput) {
  std::string tail;
  // 1 MB, far beyond a pipe's 64 KiB: the program would block if the output were not drained.
  EXPECT_EQ(run_program_reading(program({"seq", "1", "150000"}), tail, 12), 0);
  EXPECT_EQ(tail, "9999\n150000\n");
}

TEST(RunProgramReading, GivesTheExitCode) {
  std::string tail;
  EXPECT_EQ(run_program_reading(program({"printf", "a\\000b"}), tail, 100), 0);
  EXPECT_EQ(tail, std::string("a\0b", 3));
  EXPECT_EQ(run_program_reading(program({"false"}), tail, 100), 1);
  EXPECT_EQ(run_program_reading(program({"haptex-no-such-program"}), tail, 100), 127);
  EXPECT_EQ(tail, "");
}

}  // namespace
}  // namespace haptex::process
