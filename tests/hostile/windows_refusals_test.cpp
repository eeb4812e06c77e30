// haptex windows refuses what it cannot use (exit code 2, naming the file) and writes nothing then:
// an earlier output without --force, a split of another dataset, a file that is not a dataset.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/hostile/hostile_support.hpp"
#include "tests/support/small_pipeline.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {
namespace fs = std::filesystem;

TEST(WindowsRefusals, ReplacesAnEarlierFileOnlyWithForce) {
  const TempDir dir;
  const SmallPipeline& p = small_pipeline();
  const std::string out = dir.file("windows.h5");
  std::ofstream(out) << "mine";
  expect_refusal(run_haptex({"windows", p.dataset, "--split", p.split, "-o", out}), {out, "--force"});
  EXPECT_EQ(file_bytes(out), "mine");
  expect_refusal(run_haptex({"windows", p.dataset, "--split", p.split, "-o", out, "--force"}),
                 {out, "--force replaces only a file haptex wrote"});
  EXPECT_EQ(file_bytes(out), "mine");
  fs::remove(out);
  ASSERT_EQ(run_haptex({"windows", p.dataset, "--split", p.split, "-o", out}).exit_code, 0);
  struct stat first {};
  ASSERT_EQ(stat(out.c_str(), &first), 0);
  ASSERT_EQ(run_haptex({"windows", p.dataset, "--split", p.split, "-o", out, "--force"}).exit_code, 0);
  struct stat second {};
  ASSERT_EQ(stat(out.c_str(), &second), 0);
  EXPECT_NE(first.st_ino, second.st_ino) << "replaced: a new file renamed over the old one";
  EXPECT_EQ(partial_files(dir.path().string()), std::vector<std::string>{});
}

TEST(WindowsRefusals, RefusesASplitOfAnotherDataset) {
  const TempDir dir;
  const SmallPipeline& p = small_pipeline();
  nlohmann::json manifest = nlohmann::json::parse(file_bytes(p.split));
  manifest["dataset"]["sha256"] = std::string(64, '0');
  std::ofstream(dir.file("split.json")) << manifest.dump(2);
  expect_refusal(run_haptex({"windows", p.dataset, "--split", dir.file("split.json"), "-o", dir.file("w.h5")}), {dir.file("split.json"), "sha256"});
  EXPECT_FALSE(fs::exists(dir.file("w.h5")));
}

TEST(WindowsRefusals, RefusesAFileThatIsNotADataset) {
  const TempDir dir;
  std::ofstream(dir.file("d.h5")) << "not HDF5";
  expect_refusal(run_haptex({"windows", dir.file("d.h5"), "--split", small_pipeline().split, "-o", dir.file("w.h5")}), {dir.file("d.h5")});
  EXPECT_FALSE(fs::exists(dir.file("w.h5")));
}

}  // namespace
}  // namespace haptex::test
