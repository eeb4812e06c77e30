// One output file written whole (core/durable_file.hpp): a file that appears at the final name while
// the run writes (a user's, another run's) is never replaced without --force (issue 32, review 2).
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/durable_file.hpp"
#include "core/error.hpp"
#include "core/temporary_name.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex {
namespace {
namespace fs = std::filesystem;

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), {}};
}

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
  EXPECT_EQ(read_text(out), "the user's notes");
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
  EXPECT_EQ(read_text(out), "new");
  const std::string fresh = dir.file("n.json");
  write_file_durably(fresh, "first", false);
  EXPECT_EQ(read_text(fresh), "first");
  EXPECT_TRUE(temporaries_of(fresh).empty());
}

// Review 3, #3: SIGTERM between the renames of outputs that belong together (a model and its
// training log) left the model without its log. Held by hold_temporaries, the signal waits until both
// are in place, then ends the run by itself. A child process takes the signal, as a run would.
TEST(PartialFile, ASignalBetweenRenamesOfASetWaitsForTheWholeSet) {
  const test::TempDir dir;
  const std::string model = dir.file("m.h5"), log = dir.file("m.training.json");
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    remove_temporaries_on_signals();
    PartialFile a(model, false), b(log, false);
    write_text(a, "model"), write_text(b, "log");
    a.finish(), b.finish();
    {
      const auto together = hold_temporaries();
      a.commit();
      ::kill(::getpid(), SIGTERM);
      ::usleep(300000);  // time enough for the signal to end the process, were it not held
      b.commit();
    }
    ::sleep(10);  // the signal ends it here
    ::_exit(0);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM) << "status " << status;
  EXPECT_EQ(read_text(model), "model");
  EXPECT_EQ(read_text(log), "log") << "the set was cut between its renames";
  EXPECT_TRUE(temporaries_of(model).empty() && temporaries_of(log).empty());
}

}  // namespace
}  // namespace haptex
