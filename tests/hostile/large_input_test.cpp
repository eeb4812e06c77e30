// Issue 11 point 7: a press image too large to be a sensor frame is refused from its header, before
// OpenCV decodes (and allocates) it; a real sensor-sized frame still works.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>

#include "core/image_header.hpp"
#include "tests/hostile/hostile_support.hpp"
#include "tests/support/mutations.hpp"
#include "tests/support/quick_models.hpp"
#include "tests/support/small_pipeline.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {
namespace fs = std::filesystem;

void put_u32(std::string& s, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) s += char((v >> shift) & 0xff);
}

// A PNG whose header claims width x height and whose data is cut off: only the header is read.
std::string png_header_only(std::uint32_t width, std::uint32_t height) {
  std::string s("\x89PNG\r\n\x1a\n", 8);
  put_u32(s, 13);
  s += "IHDR";
  put_u32(s, width);
  put_u32(s, height);
  s += std::string("\x08\x02\x00\x00\x00", 5);
  put_u32(s, 0);  // CRC: never checked before the size
  return s;
}

TEST(LargeInput, APressImageOverTheLimitIsRefusedFromItsHeader) {
  const TempDir dir;
  std::ofstream(dir.file("huge.png"), std::ios::binary) << png_header_only(12000, 12000);
  const CommandResult r = run_haptex({"predict", quick_model(), "--image", dir.file("huge.png"), "--normal-force", "1", "--speed", "100"});
  expect_refusal(r, {dir.file("huge.png"), "12000 x 12000", "64 megapixels"});
}

// Review 12, F1: extract's --reference was decoded whole (a 1.2 MB PNG of 20000 x 20000, 1.6 GB).
TEST(LargeInput, ExtractsReferenceOverTheLimitIsRefusedFromItsHeader) {
  const TempDir dir;
  std::ofstream(dir.file("huge.png"), std::ios::binary) << png_header_only(20000, 20000);
  ASSERT_EQ(run_haptex({"capture", "record", "--device", "fake:size=160x120,lockstep", "--material", "Cork", "--presses", "1", "-o",
                        dir.file("s")}).exit_code, 0);
  const CommandResult r = run_haptex({"capture", "extract", dir.file("s/press_0.h5"), "--reference", dir.file("huge.png"), "-o", dir.file("g.h5")});
  expect_refusal(r, {dir.file("huge.png"), "20000 x 20000", "64 megapixels"});
}

TEST(LargeInput, ImageHeadersGiveTheSizeWithoutDecoding) {
  const TempDir dir;
  const cv::Mat image(37, 53, CV_8UC3, cv::Scalar(10, 20, 30));
  for (const char* name : {"a.png", "a.jpg"}) {
    ASSERT_TRUE(cv::imwrite(dir.file(name), image));
    const auto size = image_header_size(dir.file(name));
    ASSERT_TRUE(size.has_value()) << name;
    EXPECT_EQ(size->width, 53u) << name;
    EXPECT_EQ(size->height, 37u) << name;
  }
  std::ofstream(dir.file("text.png")) << "not an image";
  EXPECT_FALSE(image_header_size(dir.file("text.png")).has_value());
  std::ofstream(dir.file("cut.jpg"), std::ios::binary) << std::string("\xff\xd8\xff\xe0\x00", 5);
  EXPECT_FALSE(image_header_size(dir.file("cut.jpg")).has_value());
}

TEST(LargeInput, ASensorSizedFrameWithoutAReferenceStillWorks) {
  const TempDir dir;
  cv::Mat frame(2464, 3280, CV_8UC3);
  cv::randu(frame, 0, 255);
  ASSERT_TRUE(cv::imwrite(dir.file("mini.png"), frame));
  const CommandResult r = run_haptex({"predict", quick_model(), "--image", dir.file("mini.png"), "--normal-force", "1", "--speed", "100"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

// Review 14, F2: a trajectory or image of zeros (a sparse file, 8 GiB here and 4 KiB on disk) was read
// whole before it was judged: 5 times its size in memory, or "the file is empty" when that failed.
// Now its first line (or bytes) refuse it at once.
TEST(LargeInput, ASparseFileOfZerosIsRefusedFromItsFirstBytes) {
  const TempDir d;
  const std::string zeros = d.file("zeros.csv"), image = d.file("zeros.png");
  for (const std::string& f : {zeros, image}) {
    std::ofstream(f).close();
    fs::resize_file(f, std::uintmax_t(8) << 30);
  }
  const std::string model = quick_model(), material = small_material();
  const auto started = std::chrono::steady_clock::now();
  expect_refusal(run_haptex({"predict", model, "--material", material, "--csv", zeros}), {zeros, "line 1", "longer than 4096 bytes"});
  expect_refusal(run_haptex({"render", model, "--material", material, "--trajectory", zeros, "-o", d.file("x.wav")}),
                 {zeros, "line 1", "longer than 4096 bytes"});
  expect_refusal(run_haptex({"predict", model, "--image", image, "--normal-force", "1", "--speed", "100"}), {image, "not a PNG or JPEG"});
  EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::seconds(20)) << "8 GiB were read";
  EXPECT_FALSE(fs::exists(d.file("x.wav")));
}

// Review 23, F8: 30 000 nested groups (a 4.8 MB file) overflowed the stack of the walk every reader
// makes for links (SIGSEGV in info, qa, split, ...), and the Python package's walk did not end in 100 s.
TEST(LargeInput, GroupsNestedBeyondAnyHaptexFileAreRefusedNamingThePlace) {
  const TempDir d;
  const auto nested = [&](const std::string& name, int levels) {
    const std::string file = copy_into(d, small_pipeline().dataset, name);
    Edit e(file);
    hid_t parent = H5Gopen2(e.root().id(), ("materials/" + small_material()).c_str(), H5P_DEFAULT);
    for (int i = 0; i < levels; ++i) {
      const hid_t child = H5Gcreate2(parent, "a", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
      EXPECT_GE(child, 0);
      H5Gclose(parent);
      parent = child;
    }
    H5Gclose(parent);
    return file;
  };
  // Review 25, F4: a bound of 32 refused what 16 rounds of merging merged files write (2 levels a round).
  const std::string merged_often = nested("often.h5", 100);
  const CommandResult info = run_haptex({"info", merged_often});
  EXPECT_EQ(info.exit_code, 0) << info.err;
  const std::string dataset = nested("deep.h5", 30000);
  std::string place = "/materials/" + small_material();  // the first group beyond 1024 levels
  for (int i = 0; i < 1023; ++i) place += "/a";  // /materials/<id> and 1023 more: level 1025
  for (const std::vector<std::string>& args : {std::vector<std::string>{"info", dataset}, {"qa", dataset}, {"split", dataset, "-o", d.file("s.json")}}) {
    const CommandResult r = run_haptex(args);
    EXPECT_NE(r.exit_code, 139) << args[0] << " crashed";
    EXPECT_NE((r.out + r.err).find("is a group 1025 levels deep"), std::string::npos) << args[0] << r.out << r.err;
    EXPECT_NE((r.out + r.err).find(place), std::string::npos) << args[0] << r.out << r.err;
  }
  EXPECT_FALSE(fs::exists(d.file("s.json")));
  if (!python_has("h5py, numpy")) GTEST_SKIP() << "python3-h5py is not installed (make deps installs it)";
  const auto started = std::chrono::steady_clock::now();
  const CommandResult py = run_python({"-c", "import sys; sys.path.insert(0, sys.argv[1]); import h5py, haptex.data as h\n"
                                             "h.require_plain_objects(h5py.File(sys.argv[2], 'r'), sys.argv[2])",
                                       std::string(HAPTEX_SCHEMA_DIR) + "/../python", dataset});
  EXPECT_NE(py.exit_code, 0);
  EXPECT_NE(py.err.find("is a group 1025 levels deep"), std::string::npos) << py.err;
  EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::seconds(30));
}

}  // namespace
}  // namespace haptex::test
