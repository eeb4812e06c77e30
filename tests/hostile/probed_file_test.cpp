// Review 30, F1: the probe and haptex's HDF5 each opened the file by its path, so a file renamed over
// the input between the two (rsync, any write-then-rename program) passed the probe as the old file
// and crashed haptex as the new one (SIGSEGV). The file HDF5 opened is probed too, through HDF5's own
// descriptor, before HDF5 reads past its first headers. The seam: a stand-in probe beside a copy of
// haptex renames a damaged file over the input, then runs the real probe.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>

#include "tests/hostile/hostile_support.hpp"
#include "tests/support/mutations.hpp"
#include "tests/support/small_pipeline.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {
namespace fs = std::filesystem;

TEST(ProbedFile, AFileRenamedOverTheInputAfterTheProbeIsProbedToo) {
  const TempDir d;
  const std::string input = d.file("x.h5"), damaged = d.file("damaged.h5");
  fs::copy_file(small_pipeline().dataset, input);
  copy_with_damaged_attribute(small_pipeline().dataset, "lowpass_filter", damaged);
  ASSERT_EQ(run_haptex({"info", damaged}).exit_code, 2) << "the damage is one the probe refuses";
  fs::create_directory(d.file("bin"));
  const std::string haptex = d.file("bin/haptex"), stand_in = d.file("bin/haptex-h5-probe");
  fs::copy_file(HAPTEX_BINARY, haptex);
  {
    std::ofstream script(stand_in);
    script << "#!/bin/sh\n[ -e \"$SWAP_FROM\" ] && mv -f \"$SWAP_FROM\" \"$SWAP_TO\"\nexec \"$REAL_PROBE\" \"$@\"\n";
  }
  fs::permissions(stand_in, fs::perms::owner_all);
  const std::string real_probe = (fs::path(HAPTEX_BINARY).parent_path() / "haptex-h5-probe").string();
  const CommandResult r = run_program({"/usr/bin/env", "SWAP_FROM=" + damaged, "SWAP_TO=" + input, "REAL_PROBE=" + real_probe,
                                       "LD_LIBRARY_PATH=" + fs::path(HAPTEX_BINARY).parent_path().string(), haptex, "info", input});
  EXPECT_FALSE(fs::exists(damaged)) << "the stand-in renamed the damaged file over the input";
  expect_refusal(r, {input, "HDF5 crashes reading it", "damaged"});
}

}  // namespace
}  // namespace haptex::test
