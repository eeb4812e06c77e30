// `capture record --device replay:FILE`: file names that spell shell commands, quotes and commas
// are only names (nothing runs them, the file is found), and files that are no video, pipes and
// devices are refused with exit code 2 and nothing written.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/capture/fake_setup.hpp"
#include "tests/capture/press_videos.hpp"
#include "tests/hostile/hostile_support.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {
namespace fs = std::filesystem;

CommandResult record(const std::string& device, const std::string& session) {
  return run_haptex({"capture", "record", "--device", device, "--material", "Cork", "--presses", "10", "-o", session});
}

TEST(HostileReplay, AFileNameIsOnlyAName) {
  const TempDir dir;
  // Spaces, both quotes, back-quotes, $( ), a semicolon and commas that start no key.
  const std::string name = "take 1, \"it's\" `touch x` $(touch y); touch z,2.avi";
  const std::string video = dir.file(name);
  capture::fixtures::write_press_video(video, capture::fixtures::quick_presses(1), 60, 320, 240,
                                       cv::VideoWriter::fourcc('M', 'J', 'P', 'G'));
  const CommandResult r = record("replay:" + video + ",lockstep", dir.file("s"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json m = nlohmann::json::parse(file_bytes(dir.file("s/session.json")));
  EXPECT_EQ(m["device"]["node"], "replay:" + video) << "the name reaches the manifest as it is";
  EXPECT_EQ(m["presses"].size(), 1u);
  EXPECT_EQ(files_named(dir.path().string(), {"x", "y", "z"}), std::vector<std::string>{});
  EXPECT_EQ(files_named(fs::current_path().string(), {"x", "y", "z"}), std::vector<std::string>{});
}

TEST(HostileReplay, FilesThatAreNoVideoAreRefused) {
  const TempDir dir;
  std::ofstream(dir.file("text.avi")) << "not a video\n";
  std::ofstream(dir.file("empty.mkv"));
  std::ofstream(dir.file("text.h5")) << "not HDF5\n";
  ASSERT_EQ(::mkfifo(dir.file("pipe.avi").c_str(), 0600), 0);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {dir.file("text.avi"), "video"},
      {dir.file("empty.mkv"), "video"},
      {dir.file("text.h5"), "not an HDF5 file"},
      {dir.file("pipe.avi"), "not a regular file"},
      {"/dev/zero", "not a regular file"},
      {dir.path().string(), "is a folder"},
  };
  for (const auto& [file, why] : cases) {
    const std::string session = dir.file("s");
    expect_refusal(record("replay:" + file, session), {file, why});
    EXPECT_FALSE(fs::exists(session)) << file << ": nothing written";
  }
  expect_refusal(record("replay:caf\xe9.avi", dir.file("s")), {"--device", "not valid UTF-8", "byte 10"});
}

// Review 14, F10: a press file whose global heap (where its JPEG frames live) is damaged was exit 1
// with no place or fix in extract and replay, where qa says exit 2.
TEST(HostileReplay, APressFileWithADamagedHeapIsBadInputNamingTheFrame) {
  const TempDir dir;
  ASSERT_EQ(run_haptex({"capture", "record", "--device", "fake:size=160x120,lockstep", "--material", "Cork", "--presses", "1", "-o", dir.file("s"),
                        "-q"}).exit_code, 0);
  std::string bytes = file_bytes(dir.file("s/press_0.h5"));
  const std::size_t heap = bytes.find("GCOL", 2049);
  ASSERT_NE(heap, std::string::npos);
  bytes.replace(heap, 4, "XXXX");
  const std::string damaged = dir.file("damaged.h5");
  std::ofstream(damaged, std::ios::binary) << bytes;
  expect_refusal(run_haptex({"capture", "extract", damaged, "-o", dir.file("g.h5"), "--no-sheets"}), {damaged, "/frames, element", "damaged"});
  expect_refusal(record("replay:" + damaged + ",lockstep", dir.file("r")), {damaged, "/frames, element", "damaged"});
  EXPECT_FALSE(fs::exists(dir.file("g.h5")));
  EXPECT_FALSE(fs::exists(dir.file("r")));
}

}  // namespace
}  // namespace haptex::test
