// Review 27, F1: one damaged byte in an attribute's message header (the high byte of its name length)
// made libhdf5 1.10 crash (SIGSEGV, exit 139) in info, qa, split, view, trajectory, merge, align,
// capture extract and capture record's replay, and split, view and extract left their temporaries.
// haptex-h5-probe reads the file's structure first, in a process of its own (core/h5/structure_probe.hpp):
// the file is refused as damaged, exit 2, naming it, with nothing left behind.
#include <gtest/gtest.h>

#include <filesystem>

#include "tests/hostile/hostile_support.hpp"
#include "tests/support/mutations.hpp"
#include "tests/support/small_pipeline.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {

namespace fs = std::filesystem;

// Every command refuses `damaged`, naming it, and leaves nothing in `d`'s folder but what was there.
void expect_refused_everywhere(const TempDir& d, const std::string& damaged, const std::vector<std::vector<std::string>>& commands) {
  for (const std::vector<std::string>& command : commands) {
    SCOPED_TRACE(command.front());
    expect_refusal(run_haptex(command), {damaged, "damaged"});
    EXPECT_EQ(partial_files(d.path()), std::vector<std::string>{});
  }
}

TEST(DamagedHeader, ADatasetWithADamagedAttributeHeaderIsRefusedByEveryReader) {
  const SmallPipeline& p = small_pipeline();
  const TempDir d;
  const std::string dataset = d.file("d.h5");
  copy_with_damaged_attribute(p.dataset, "lowpass_filter", dataset);
  const std::string material = small_material();
  expect_refused_everywhere(d, dataset,
                            {{"info", dataset},
                             {"qa", dataset},
                             {"split", dataset, "-o", d.file("s.json")},
                             {"view", dataset, "-o", d.file("site")},
                             {"trajectory", dataset, "--material", material, "-o", d.file("t.csv")},
                             {"merge", dataset, "-o", d.file("m.h5")}});
  for (const char* output : {"s.json", "s.plots", "site", "t.csv", "m.h5"}) EXPECT_FALSE(fs::exists(d.file(output))) << output;
}

// Review 28, F3: named by a descriptor of haptex's own (/dev/stdin, /dev/fd/N), the file was not
// opened by the probe, and haptex read it unprobed: SIGSEGV. The probe now reads the file haptex opened.
TEST(DamagedHeader, AFileNamedByADescriptorIsProbedToo) {
  const TempDir d;
  const std::string dataset = d.file("d.h5");
  copy_with_damaged_attribute(small_pipeline().dataset, "lowpass_filter", dataset);
  for (const std::vector<std::string>& command :
       {std::vector<std::string>{"info", "/dev/stdin"}, {"qa", "/dev/stdin"}, {"split", "/dev/stdin", "-o", d.file("s.json")}}) {
    SCOPED_TRACE(command.front());
    expect_refusal(run_haptex_fed(command, dataset), {"/dev/stdin", "damaged"});
    EXPECT_EQ(partial_files(d.path()), std::vector<std::string>{});
  }
}

// With haptex's standard input closed (`<&-`, as a daemon may start it), the file opened for the probe
// was descriptor 0 and was replaced by /dev/null in the child before it was passed: read unprobed, SIGSEGV.
TEST(DamagedHeader, AFileIsProbedWithStandardInputClosed) {
  if (!python_has("os")) GTEST_SKIP() << "python3 is not installed";
  const TempDir d;
  const std::string dataset = d.file("d.h5");
  copy_with_damaged_attribute(small_pipeline().dataset, "lowpass_filter", dataset);
  const CommandResult r = run_python({"-c", "import os, subprocess, sys\n"
                                            "sys.exit(subprocess.run(sys.argv[1:], preexec_fn=lambda: os.close(0)).returncode)",
                                      haptex_binary(), "info", dataset});
  expect_refusal(r, {dataset, "damaged"});
}

TEST(DamagedHeader, AGelsightFileWithADamagedAttributeHeaderIsRefusedByAlign) {
  const SmallPipeline& p = small_pipeline();
  const TempDir d;
  const std::string gelsight = d.file("g.h5");
  copy_with_damaged_attribute(p.gelsight, "fps", gelsight);
  expect_refused_everywhere(d, gelsight,
                            {{"info", gelsight}, {"align", "--recordings", p.recordings, "--gelsight", gelsight, "-o", d.file("a.h5")}});
  EXPECT_FALSE(fs::exists(d.file("a.h5")));
}

// Review 31, F4: one flipped bit in a float32 datatype's size (4 -> 255 bytes) made qa, merge, view and
// align read past HDF5's buffers (SIGSEGV; view left its .partial folder). A number type no HDF5 writer
// makes is damage, refused by the probe and by every read.
TEST(DamagedHeader, AFloatOfAnImpossibleSizeIsRefusedByEveryReader) {
  const SmallPipeline& p = small_pipeline();
  const TempDir d;
  for (std::size_t nth = 0; nth < 4; ++nth) {
    SCOPED_TRACE(nth);
    const std::string dataset = d.file("d" + std::to_string(nth) + ".h5"), recordings = d.file("r" + std::to_string(nth) + ".h5");
    ASSERT_TRUE(copy_with_damaged_float_size(p.dataset, nth, dataset));
    ASSERT_TRUE(copy_with_damaged_float_size(p.recordings, nth, recordings));
    expect_refused_everywhere(d, dataset, {{"qa", dataset}, {"merge", dataset, "-o", d.file("m.h5")}, {"view", dataset, "-o", d.file("site")}});
    expect_refused_everywhere(d, recordings, {{"qa", recordings}, {"align", "--recordings", recordings, "--gelsight", p.gelsight, "-o", d.file("a.h5")}});
  }
  for (const char* output : {"m.h5", "site", "a.h5"}) EXPECT_FALSE(fs::exists(d.file(output))) << output;
}

TEST(DamagedHeader, APressFileWithADamagedRootAttributeIsRefusedByExtractAndReplay) {
  const TempDir d;
  ASSERT_EQ(run_haptex({"capture", "record", "--device", "fake:size=160x120,lockstep", "--material", "Cork", "--presses", "1", "-o",
                        d.file("s")}).exit_code, 0);
  fs::create_directory(d.file("take"));
  const std::string press = d.file("take/press_0.h5");
  copy_with_damaged_attribute(d.file("s/press_0.h5"), "material_id", press);
  expect_refused_everywhere(d, press,
                            {{"capture", "extract", d.file("take"), "-o", d.file("g.h5")},
                             {"capture", "record", "--device", "replay:" + press + ",lockstep", "--material", "Cork", "-o", d.file("r")}});
  for (const char* output : {"g.h5", "g_sheets", "r"}) EXPECT_FALSE(fs::exists(d.file(output))) << output;
}

}  // namespace
}  // namespace haptex::test
