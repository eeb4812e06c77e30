// Issue 31's goals on real footage of other labs (docs/capture.md, "Measured"), checked by
// tests/e2e/other_labs_footage.py on a sample: every 7th PhysiCLeAR video and every third GelSight
// Wedge grasp with its force log and its still clips. The footage is not in the repository (licences,
// size): it is read from $HAPTEX_FOOTAGE, else ../footage beside the repository, where the snapshots of
// clear-nus/octopi and GelSight-lab/EstimateModulus are checked out (the script's header says how),
// and the test skips when it, python3-opencv or ffmpeg is absent.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "tests/support/run_haptex.hpp"

namespace haptex::test {
namespace {

const std::string kSource = std::string(HAPTEX_SCHEMA_DIR) + "/../";

std::string footage_folder() {
  const char* env = std::getenv("HAPTEX_FOOTAGE");
  return env ? env : kSource + "../footage";
}

CommandResult check(const std::string& groups, const std::string& every) {
  return run_python({kSource + "tests/e2e/other_labs_footage.py", haptex_binary(), footage_folder(), "--groups", groups, "--every",
                     every, "--check", "--list-misses"});
}

TEST(OtherLabsFootage, PhysiclearPressesAreFound) {
  const CommandResult r = check("physiclear", "7");
  if (r.exit_code == 77) GTEST_SKIP() << r.err;
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
}

TEST(OtherLabsFootage, WedgeGraspsAreFoundAtTheirForcePeakAndStillClipsGiveNone) {
  const CommandResult r = check("wedge", "3");
  if (r.exit_code == 77) GTEST_SKIP() << r.err;
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
}

}  // namespace
}  // namespace haptex::test
