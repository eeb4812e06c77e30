// Output folders written whole (core/partial_directory.hpp): the old folder or the new one, never
// a mixture, never a folder of the user's emptied.
#include "core/partial_directory.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.hpp"
#include "core/temporary_name.hpp"
#include "tests/support/temp_dir.hpp"
#include "tests/support/file_text.hpp"

namespace haptex {
namespace {
namespace fs = std::filesystem;

void write_text(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

std::string refusal(const std::string& dir, const FolderOptions& options) {
  try {
    PartialDirectory partial(dir, options);
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::bad_input);
    return e.what();
  }
  return "";
}

// A name with quotes, back-quotes and a space: nothing here reaches a shell.
const std::string kName = "out 'a' \"b\" `c`";

TEST(PartialDirectory, AppearsWholeOnCommitWithItsFileList) {
  const test::TempDir dir;
  const std::string out = dir.file(kName);
  {
    PartialDirectory partial(out, {false, "report folder", "-o", "haptex test"});
    EXPECT_EQ(temporaries_of(out), std::vector<std::string>{partial.path()});
    write_text(fs::path(partial.path()) / "a.txt", "new");
    write_text(fs::path(partial.path()) / "sub" / "b.txt", "deep");
    EXPECT_FALSE(fs::exists(out));
    partial.commit();
  }
  EXPECT_EQ(test::file_text(fs::path(out) / "a.txt"), "new");
  EXPECT_EQ(test::file_text(fs::path(out) / "sub" / "b.txt"), "deep");
  EXPECT_TRUE(fs::exists(fs::path(out) / "haptex-files.json"));
  EXPECT_TRUE(temporaries_of(out).empty());
}

TEST(PartialDirectory, WithoutCommitLeavesTheOldFolderAsItWas) {
  const test::TempDir dir;
  const std::string out = dir.file("report");
  { PartialDirectory first(out, {}); write_text(fs::path(first.path()) / "a.txt", "old"); first.commit(); }
  {
    PartialDirectory failed(out, {true});
    write_text(fs::path(failed.path()) / "a.txt", "half");
  }  // an exception half way: no commit
  EXPECT_EQ(test::file_text(fs::path(out) / "a.txt"), "old");
  EXPECT_TRUE(temporaries_of(out).empty());
}

TEST(PartialDirectory, ReplacesOnlyWithForceAndOnlyWhatHaptexWrote) {
  const test::TempDir dir;
  const std::string out = dir.file("report");
  { PartialDirectory first(out, {}); write_text(fs::path(first.path()) / "old.txt", "old"); first.commit(); }
  const std::string without = refusal(out, {false, "report folder", "-o"});
  EXPECT_NE(without.find("already exists and is not empty"), std::string::npos) << without;
  EXPECT_NE(without.find("--force"), std::string::npos) << without;
  {
    PartialDirectory again(out, {true});
    write_text(fs::path(again.path()) / "new.txt", "new");
    again.commit();
  }
  EXPECT_FALSE(fs::exists(fs::path(out) / "old.txt")) << "replaced whole, nothing of the earlier run next to the new one";
  EXPECT_EQ(test::file_text(fs::path(out) / "new.txt"), "new");
  write_text(fs::path(out) / "mine.txt", "the user's");
  const std::string foreign = refusal(out, {true});
  EXPECT_NE(foreign.find("mine.txt"), std::string::npos) << foreign;
  EXPECT_EQ(test::file_text(fs::path(out) / "mine.txt"), "the user's");
}

TEST(PartialDirectory, AFileOfTheUsersAppearingMeanwhileStopsTheCommit) {
  const test::TempDir dir;
  const std::string out = dir.file("report");
  { PartialDirectory first(out, {}); first.commit(); }
  PartialDirectory again(out, {true});
  write_text(fs::path(out) / "mine.txt", "the user's");
  EXPECT_THROW(again.commit(), Error);
  EXPECT_EQ(test::file_text(fs::path(out) / "mine.txt"), "the user's");
}

TEST(PartialDirectory, RefusesASecondWriterAFileInItsPlaceAndAMissingParent) {
  const test::TempDir dir;
  const std::string out = dir.file("report");
  {
    PartialDirectory first(out, {});
    const std::string locked = refusal(out, {true, "report folder"});
    EXPECT_NE(locked.find("another haptex run"), std::string::npos) << locked;
    EXPECT_TRUE(fs::exists(first.path())) << "the second writer leaves the first one's work alone";
  }
  write_text(dir.path() / "plain", "x");
  EXPECT_NE(refusal(dir.file("plain"), {true}).find("not a folder"), std::string::npos);
  EXPECT_NE(refusal(dir.file("missing/report"), {}).find("does not exist"), std::string::npos);
  EXPECT_NE(refusal(dir.file("."), {}).find("not a name"), std::string::npos);
  fs::create_directory(dir.path() / "empty");
  PartialDirectory into_empty(dir.file("empty"), {});  // an empty folder is no one's work
  into_empty.commit();
  EXPECT_TRUE(fs::exists(dir.path() / "empty" / "haptex-files.json"));
}

}  // namespace
}  // namespace haptex
