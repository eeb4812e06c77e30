// Review 30, F1: the probe and haptex's HDF5 each opened the file by its path, so a file renamed over
// the input between the two (rsync, any write-then-rename program) passed the probe as the old file
// and crashed haptex as the new one (SIGSEGV). The file HDF5 opened is probed too, through HDF5's own
// descriptor, before HDF5 reads past its first headers. Review 31, F1: once that file was renamed over
// in turn, the probe's HDF5 could not open /dev/fd/3 (realpath of a deleted file), and "not opened" was
// taken as "read". The seam: a stand-in probe beside a copy of haptex renames a file over the input at
// each call, then runs the real probe.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tests/hostile/hostile_support.hpp"
#include "tests/support/mutations.hpp"
#include "tests/support/small_pipeline.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {
namespace fs = std::filesystem;

// `haptex info INPUT` (a good dataset) with a stand-in probe that, before its first and second runs,
// renames FIRST and then SECOND over the input (when they exist).
CommandResult info_while_renamed_over(const TempDir& d, const std::string& input, const std::string& first, const std::string& second) {
  fs::create_directory(d.file("bin"));
  const std::string haptex = d.file("bin/haptex"), stand_in = d.file("bin/haptex-h5-probe");
  fs::copy_file(HAPTEX_BINARY, haptex);
  {
    std::ofstream script(stand_in);
    script << "#!/bin/sh\nif [ -e \"$FIRST\" ]; then mv -f \"$FIRST\" \"$INPUT\"; elif [ -e \"$SECOND\" ]; then mv -f \"$SECOND\" \"$INPUT\"; fi\n"
              "exec \"$REAL_PROBE\" \"$@\"\n";
  }
  fs::permissions(stand_in, fs::perms::owner_all);
  const fs::path built = fs::path(HAPTEX_BINARY).parent_path();
  return run_program({"/usr/bin/env", "FIRST=" + first, "SECOND=" + second, "INPUT=" + input, "REAL_PROBE=" + (built / "haptex-h5-probe").string(),
                      "LD_LIBRARY_PATH=" + built.string(), haptex, "info", input});
}

TEST(ProbedFile, AFileRenamedOverTheInputAfterTheProbeIsProbedToo) {
  const TempDir d;
  const std::string input = d.file("x.h5"), damaged = d.file("damaged.h5");
  fs::copy_file(small_pipeline().dataset, input);
  copy_with_damaged_attribute(small_pipeline().dataset, "lowpass_filter", damaged);
  ASSERT_EQ(run_haptex({"info", damaged}).exit_code, 2) << "the damage is one the probe refuses";
  const CommandResult r = info_while_renamed_over(d, input, damaged, "");
  EXPECT_FALSE(fs::exists(damaged)) << "the stand-in renamed the damaged file over the input";
  expect_refusal(r, {input, "HDF5 crashes reading it", "damaged"});
}

TEST(ProbedFile, TheFileHDF5OpenedIsProbedWhenRenamedOverInTurn) {
  const TempDir d;
  const std::string input = d.file("x.h5"), damaged = d.file("damaged.h5"), good = d.file("good.h5");
  fs::copy_file(small_pipeline().dataset, input);
  fs::copy_file(small_pipeline().dataset, good);
  copy_with_damaged_attribute(small_pipeline().dataset, "lowpass_filter", damaged);
  const CommandResult r = info_while_renamed_over(d, input, damaged, good);
  EXPECT_FALSE(fs::exists(good)) << "the stand-in renamed the good file over the damaged one HDF5 had open";
  expect_refusal(r, {input, "HDF5 crashes reading it", "damaged"});
}

// Review 31, F6: any probe exit but "refused" or a crash was taken for "read": as process 1 of a
// container, haptex made its probe think itself orphaned (exit 65), and every file was read unprobed.
// Only a probe that read it all says so; any other end is said as it is.
TEST(ProbedFile, OnlyAProbeThatReadItAllLetsTheFileBeRead) {
  const TempDir d;
  const std::string damaged = d.file("damaged.h5");
  copy_with_damaged_attribute(small_pipeline().dataset, "lowpass_filter", damaged);
  fs::create_directory(d.file("bin"));
  const std::string haptex = d.file("bin/haptex"), stand_in = d.file("bin/haptex-h5-probe");
  fs::copy_file(HAPTEX_BINARY, haptex);
  std::ofstream(stand_in) << "#!/bin/sh\nexit 65\n";
  fs::permissions(stand_in, fs::perms::owner_all);
  const std::string libraries = "LD_LIBRARY_PATH=" + fs::path(HAPTEX_BINARY).parent_path().string();
  const CommandResult r = run_program({"/usr/bin/env", libraries, haptex, "info", damaged});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("ended with exit code 65, which says nothing of the file"), std::string::npos) << r.err;
  if (!python_has("h5py, numpy")) return;
  const CommandResult py = run_program({"/usr/bin/env", libraries, "HAPTEX_BINARY=" + haptex, "/usr/bin/python3", "-c",
                                        "import sys; sys.path.insert(0, sys.argv[1]); import haptex.data as d\n"
                                        "try:\n    d.open_hdf5(sys.argv[2]); print('READ')\n"
                                        "except d.HaptexFileError as e:\n    print(e)",
                                        std::string(HAPTEX_SCHEMA_DIR) + "/../python", damaged});
  EXPECT_NE(py.out.find("ended with exit code 65, which says nothing of the file"), std::string::npos) << py.out << py.err;
}

}  // namespace
}  // namespace haptex::test
