// One output file written whole (core/durable_file.hpp): a file that appears at the final name while
// the run writes (a user's, another run's) is never replaced without --force (issue 32, review 2).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/durable_file.hpp"
#include "core/error.hpp"
#include "core/temporary_name.hpp"
#include "tests/support/no_free_descriptor.hpp"
#include "tests/support/temp_dir.hpp"
#include "tests/support/file_text.hpp"

namespace haptex {
namespace {
namespace fs = std::filesystem;

TEST(PartialFile, AFileThatAppearsMeanwhileIsKeptWithoutForce) {
  const test::TempDir dir;
  const std::string out = dir.file("x.training.json");
  {
    PartialFile partial(out, false);
    write_text(partial, "haptex's log");
    std::ofstream(out) << "the user's notes";  // appears while the run writes
    try {
      partial.commit();
      ADD_FAILURE() << "the user's file was replaced";
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), Error::Kind::bad_input);
      EXPECT_NE(std::string(e.what()).find(out + ": appeared while this run was writing it"), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(test::file_text(out), "the user's notes");
  EXPECT_TRUE(temporaries_of(out).empty());
}

TEST(PartialFile, WithForceTheFileIsReplacedAndWithoutOneANewFileAppears) {
  const test::TempDir dir;
  const std::string out = dir.file("m.json");
  std::ofstream(out) << "an earlier output";
  {
    PartialFile partial(out, true);
    write_text(partial, "new");
    partial.commit();
  }
  EXPECT_EQ(test::file_text(out), "new");
  const std::string fresh = dir.file("n.json");
  write_file_durably(fresh, "first", false);
  EXPECT_EQ(test::file_text(fresh), "first");
  EXPECT_TRUE(temporaries_of(fresh).empty());
}

// Review 5: --force checked a JSON, WAV or CSV output as haptex's before the work only, so a user's
// file that took its place while the run wrote was replaced.
TEST(PartialFile, WithForceAFileThatIsNoLongerHaptexsIsKept) {
  const test::TempDir dir;
  const std::string out = dir.file("s.json");
  std::ofstream(out) << "{\"format\": \"split/1\"}";
  const auto still_haptexs = [](const std::string& path) {
    if (test::file_text(path).find("split/1") == std::string::npos)
      throw input_error(path, "", "--force replaces only a split manifest, and this file is not one", "Move it away");
  };
  {
    PartialFile partial(out, true, still_haptexs);
    write_text(partial, "new");
    std::ofstream(out) << "the user's thesis";  // takes the place of haptex's file while the run writes
    try {
      partial.commit();
      ADD_FAILURE() << "the user's file was replaced";
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), Error::Kind::bad_input);
      EXPECT_NE(std::string(e.what()).find("this file is not one"), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(test::file_text(out), "the user's thesis");
  EXPECT_TRUE(temporaries_of(out).empty());
  {
    std::ofstream(out) << "{\"format\": \"split/1\"}";
    PartialFile partial(out, true, still_haptexs);
    write_text(partial, "new");
    partial.commit();
  }
  EXPECT_EQ(test::file_text(out), "new");
}

// Review 25, F2: the folder was opened to be synced after the rename, so a run out of descriptors
// failed (exit 1) with its output already whole under the final name. It fails before the rename, and
// says the limit, not "cannot open .".
TEST(PartialFile, OutOfDescriptorsFailsBeforeTheOutputIsInPlace) {
  const test::TempDir dir;
  { std::ofstream(dir.file("a.tmp")) << "done"; }
  try {
    const test::NoFreeDescriptor none;
    durable_rename(dir.file("a.tmp"), dir.file("a.csv"), false);
    FAIL() << "renamed without a descriptor to sync its folder";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::failed);
    EXPECT_NE(std::string(e.what()).find("ulimit -n"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir.file("a.csv")));
  EXPECT_TRUE(fs::exists(dir.file("a.tmp")));
}

}  // namespace
}  // namespace haptex
