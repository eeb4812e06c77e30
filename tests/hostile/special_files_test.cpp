// Issue 32, class 7: a FIFO, a device or a folder where a command reads a file is refused by name at
// once (core/input_file.hpp), never read until the end of time. A watchdog opens each FIFO for writing
// after 20 s, so that a command that does block fails this test instead of hanging it.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <thread>

#include "tests/hostile/hostile_support.hpp"
#include "tests/support/quick_models.hpp"
#include "tests/support/small_pipeline.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {
namespace fs = std::filesystem;

class Watchdog {
 public:
  explicit Watchdog(std::string fifo) : fifo_(std::move(fifo)), thread_([this] { watch(); }) {}
  ~Watchdog() {
    done_ = true;
    thread_.join();
  }

 private:
  void watch() {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (!done_) {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      if (std::chrono::steady_clock::now() < deadline) continue;
      const int fd = ::open(fifo_.c_str(), O_WRONLY | O_NONBLOCK);  // succeeds only while a reader waits
      if (fd >= 0) ::close(fd);
    }
  }
  std::string fifo_;
  std::atomic<bool> done_{false};
  std::thread thread_;
};

TEST(SpecialFiles, AFifoAsInputIsRefusedAtOnce) {
  const SmallPipeline& p = small_pipeline();
  const TempDir d;
  const std::string fifo = d.file("pipe.h5"), csv = d.file("pipe.csv"), json = d.file("pipe.json");
  for (const std::string& f : {fifo, csv, json}) ASSERT_EQ(::mkfifo(f.c_str(), 0600), 0);
  const std::string out = d.file("out");
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"info", fifo}, fifo},
      {{"qa", fifo}, fifo},
      {{"split", fifo, "-o", out + ".json"}, fifo},
      {{"merge", fifo, "-o", out + ".h5"}, fifo},
      {{"convert", "hatt", csv, "-o", out + ".h5"}, csv},
      {{"capture", "extract", fifo, "-o", out + ".h5"}, fifo},
      {{"windows", p.dataset, "--split", json, "-o", out + ".h5"}, json},
      {{"evaluate", p.dataset, "--split", p.split, "--model", quick_model(), "--truth", fifo, "-o", out}, fifo},
      {{"evaluate", p.dataset, "--split", p.split, "--predictions", "x=" + fifo, "-o", out}, fifo},
      {{"predict", quick_model(), "--material", small_material(), "--csv", csv}, csv},
      {{"render", quick_model(), "--material", small_material(), "--trajectory", csv, "-o", out + ".wav"}, csv},
  };
  for (const auto& [args, named] : cases) {
    SCOPED_TRACE(args.front() + " " + args[1]);
    const Watchdog watchdog(named);
    const auto start = std::chrono::steady_clock::now();
    expect_refusal(run_haptex(args), {named, "FIFO"});
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(15)) << "it waited on the FIFO";
  }
  EXPECT_EQ(partial_files(d.path().string()), std::vector<std::string>{});
}

// Review 9, F2: /proc/kmsg stats as a regular file of size 0, and `convert hatt --map /proc/kmsg`
// blocked in read() for ever. Every file of the kernel's file systems is refused by name at once
// (/proc/self/status stands in for it here: it never blocks, so the test cannot hang).
TEST(SpecialFiles, AFileOfTheKernelIsRefused) {
  const SmallPipeline& p = small_pipeline();
  const TempDir d;
  const std::string recordings = (fs::path(p.recordings).parent_path() / "synth" / "recordings").string();
  for (const std::string& kernel : {std::string("/proc/self/status"), std::string("/sys/kernel/mm/transparent_hugepage/enabled")}) {
    if (!fs::exists(kernel)) continue;
    SCOPED_TRACE(kernel);
    expect_refusal(run_haptex({"convert", "hatt", recordings, "--map", kernel, "-o", d.file("r.h5")}), {kernel, "a file of the kernel"});
    expect_refusal(run_haptex({"info", kernel}), {kernel, "a file of the kernel"});
    expect_refusal(run_haptex({"windows", p.dataset, "--split", kernel, "-o", d.file("w.h5")}), {kernel, "a file of the kernel"});
  }
  EXPECT_TRUE(fs::is_empty(d.path()));
}

TEST(SpecialFiles, ADeviceOrAFolderAsInputIsRefused) {
  const TempDir d;
  expect_refusal(run_haptex({"info", "/dev/zero"}), {"/dev/zero", "a device"});
  expect_refusal(run_haptex({"qa", d.path().string()}), {d.path().string(), "folder"});
  fs::create_symlink("/dev/zero", d.file("zero.csv"));
  expect_refusal(run_haptex({"convert", "hatt", d.file("zero.csv"), "-o", d.file("r.h5")}), {"zero.csv", "a device"});
}

TEST(SpecialFiles, AFifoAsImageIsRefusedAtOnce) {
  const TempDir d;
  const std::string fifo = d.file("press.png");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const Watchdog watchdog(fifo);
  expect_refusal(run_haptex({"predict", quick_model(), "--image", fifo, "--normal-force", "1", "--speed", "100"}), {fifo, "FIFO"});
}

// A FIFO or a dangling link carrying an input's name inside an input folder is refused by name, not
// skipped (issue 32, class 7, second review).
TEST(SpecialFiles, AFifoOrADanglingLinkInsideAnInputFolderIsRefused) {
  const fs::path synth = fs::path(small_pipeline().recordings).parent_path() / "synth";
  const TempDir d;
  fs::create_directories(d.file("hd"));
  fs::create_directories(d.file("ed"));
  fs::create_directories(d.file("md"));
  fs::create_directories(d.file("ev"));
  for (const auto& e : fs::directory_iterator(synth / "recordings")) {
    fs::copy_file(e.path(), d.file("hd/" + e.path().filename().string()));
    break;
  }
  fs::copy_file(synth / "gelsight" / "Woven 1" / "press_0.avi", d.file("ed/press_0.avi"));
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {d.file("hd/zz.xml.gz"), {"convert", "hatt", d.file("hd"), "-o", d.file("r.h5")}},
      {d.file("ed/p9.avi"), {"capture", "extract", d.file("ed"), "-o", d.file("g.h5")}},
      {d.file("md/Models_Foo.xml"), {"synth", "hatt", "--models", d.file("md"), "-o", d.file("syn")}},
      // Review 4, #13: evaluate said "the directory holds no .xml files".
      {d.file("ev/Models_Sandpaper 1.xml"), {"evaluate", small_pipeline().dataset, "--split", small_pipeline().split, "--model",
                                             quick_model(), "--baseline", "hatt-published", "--hatt-models", d.file("ev"), "-o",
                                             d.file("rep")}},
  };
  for (const auto& [fifo, args] : cases) {
    SCOPED_TRACE(fifo);
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const Watchdog watchdog(fifo);
    expect_refusal(run_haptex(args), {fifo, "FIFO"});
  }
  fs::remove(d.file("hd/zz.xml.gz"));
  fs::create_symlink(d.file("nowhere.xml"), d.file("hd/gone.xml"));
  expect_refusal(run_haptex({"convert", "hatt", d.file("hd"), "-o", d.file("r.h5")}), {d.file("hd/gone.xml")});
  EXPECT_EQ(partial_files(d.path().string()), std::vector<std::string>{});
}

// Review 14, F8: a dangling link of any name in an input folder (a material's folder, a frame folder,
// a folder of recordings whose disk moved) was skipped without a word and its data silently missing.
// A link to a real folder is followed, and one to a folder holding it is refused.
TEST(SpecialFiles, ADanglingLinkOfAnyNameInAnInputFolderIsRefused) {
  const fs::path synth = fs::path(small_pipeline().recordings).parent_path() / "synth";
  const TempDir d;
  fs::create_directories(d.file("g/Cork"));
  fs::copy_file(synth / "gelsight" / "Woven 1" / "press_0.avi", d.file("g/Cork/press_0.avi"));
  fs::create_directories(d.file("r/own"));
  fs::create_directories(d.file("elsewhere"));
  std::vector<fs::path> recordings;
  for (const auto& e : fs::directory_iterator(synth / "recordings")) recordings.push_back(e.path());
  ASSERT_GE(recordings.size(), 2u);
  fs::copy_file(recordings[0], d.file("r/own/" + recordings[0].filename().string()));
  fs::copy_file(recordings[1], d.file("elsewhere/" + recordings[1].filename().string()));
  for (const std::string& link : {d.file("g/Felt"), d.file("g/Cork/press_1")}) {
    SCOPED_TRACE(link);
    fs::create_symlink(d.file("moved-disk"), link);
    expect_refusal(run_haptex({"capture", "extract", d.file("g"), "-o", d.file("g.h5"), "--no-sheets"}),
                   {link, "symbolic link to a file that does not exist"});
    EXPECT_FALSE(fs::exists(d.file("g.h5")));
    fs::remove(link);
  }
  fs::create_symlink(d.file("elsewhere"), d.file("r/more"));
  ASSERT_EQ(run_haptex({"convert", "hatt", d.file("r"), "-o", d.file("r.h5"), "-q"}).exit_code, 0);
  const CommandResult info = run_haptex({"info", d.file("r.h5"), "--json"});
  EXPECT_NE(info.out.find(recordings[1].filename().string()), std::string::npos) << "the linked folder's recording: " << info.out;
  fs::create_symlink(d.file("moved-disk"), d.file("r/own/morerecs"));
  expect_refusal(run_haptex({"convert", "hatt", d.file("r"), "-o", d.file("r2.h5")}), {d.file("r/own/morerecs"), "does not exist"});
  fs::remove(d.file("r/own/morerecs"));
  fs::create_symlink(d.file("r"), d.file("r/own/loop"));
  expect_refusal(run_haptex({"convert", "hatt", d.file("r"), "-o", d.file("r2.h5")}), {d.file("r/own/loop"), "holds the folder it is in"});
  EXPECT_FALSE(fs::exists(d.file("r2.h5")));
}

}  // namespace
}  // namespace haptex::test
