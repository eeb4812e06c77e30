// Outputs that belong together appear together or not at all (core/output_set.hpp): a member that
// cannot take its place stops the set before any rename, a rename that fails takes back the ones
// already done (the earlier versions they replaced included), and a signal waits for the whole set.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "core/durable_file.hpp"
#include "core/error.hpp"
#include "core/output_set.hpp"
#include "core/owned_folder.hpp"
#include "core/partial_directory.hpp"
#include "core/temporary_name.hpp"
#include "tests/support/temp_dir.hpp"
#include "tests/support/file_text.hpp"

namespace haptex {
namespace {
namespace fs = std::filesystem;

// A member whose rename does `after` once it is done: the narrowest seam to a failure (or a signal)
// between the renames of a set.
class Then : public StagedOutput {
 public:
  Then(StagedOutput& real, std::function<void()> after) : real_(real), after_(std::move(after)) {}
  void finish() override { real_.finish(); }
  void check_place() const override { real_.check_place(); }
  void put_in_place() override {
    real_.put_in_place();
    after_();
  }
  void take_back() noexcept override { real_.take_back(); }
  void drop_earlier() override { real_.drop_earlier(); }

 private:
  StagedOutput& real_;
  std::function<void()> after_;
};

// A folder of haptex's at dir, holding `file` with `text`.
void haptex_folder(const std::string& dir, const std::string& text) {
  fs::create_directory(dir);
  std::ofstream(dir + "/a.txt") << text;
  write_file_list(dir, "haptex test");
}

TEST(OutputSet, AFolderThatAppearsAtAMembersNameStopsTheSetBeforeAnyRename) {
  const test::TempDir dir;
  const std::string manifest = dir.file("s.json"), plots = dir.file("s.plots");
  {
    PartialFile a(manifest, false);
    write_text(a, "manifest");
    PartialDirectory b(plots, {false, "plot folder", "-o", "haptex test"});
    b.fill([](const std::string& d) { std::ofstream(d + "/p.png") << "png"; });
    fs::create_directory(plots);
    std::ofstream(plots + "/mine.txt") << "precious";  // review 4, 3a: the user's folder appeared meanwhile
    EXPECT_THROW(commit_together({&a, &b}), Error);
  }
  EXPECT_FALSE(fs::exists(manifest)) << "a manifest without its plots";
  EXPECT_EQ(test::file_text(plots + "/mine.txt"), "precious");
  EXPECT_TRUE(temporaries_of(manifest).empty() && temporaries_of(plots).empty());
}

TEST(OutputSet, ARenameThatFailsTakesBackTheOnesDoneAndTheEarlierVersions) {
  const test::TempDir dir;
  const std::string model = dir.file("m.h5"), log = dir.file("m.training.json"), plots = dir.file("m.plots");
  std::ofstream(model) << "old model";
  haptex_folder(plots, "old plots");
  {
    PartialFile a(model, true);
    write_text(a, "new model");
    PartialDirectory b(plots, {true, "plot folder", "-o", "haptex test"});
    b.fill([](const std::string& d) { std::ofstream(d + "/a.txt") << "new plots"; });
    PartialFile c(log, false);
    write_text(c, "log");
    Then b_then_fail(b, [&] { std::ofstream(log) << "appeared"; });  // c's rename (NOREPLACE) now fails
    EXPECT_THROW(commit_together({&a, &b_then_fail, &c}), Error);
  }
  EXPECT_EQ(test::file_text(model), "old model");
  EXPECT_EQ(test::file_text(plots + "/a.txt"), "old plots");
  EXPECT_EQ(test::file_text(log), "appeared");
  EXPECT_TRUE(temporaries_of(model).empty() && temporaries_of(plots).empty() && temporaries_of(log).empty());
}

TEST(OutputSet, AnEarlierOutputIsRetiredWithTheSetAndKeptWhenItFails) {
  const test::TempDir dir;
  const std::string manifest = dir.file("s.json"), plots = dir.file("s.plots"), mine = dir.file("mine.plots");
  const auto retire = [](const std::string& d) { return is_haptex_folder(d, "haptex test"); };
  haptex_folder(plots, "old plots");
  {
    PartialFile a(manifest, false);
    write_text(a, "first");
    EarlierOutput old_plots(plots, retire);
    Then fail(a, [] { throw failure("a rename failed"); });
    EXPECT_THROW(commit_together({&old_plots, &fail}), Error);
  }
  EXPECT_EQ(test::file_text(plots + "/a.txt"), "old plots") << "put back";
  EXPECT_FALSE(fs::exists(manifest));
  {
    PartialFile a(manifest, false);
    write_text(a, "second");
    EarlierOutput old_plots(plots, retire);
    fs::create_directory(mine);
    std::ofstream(mine + "/mine.txt") << "precious";
    EarlierOutput users(mine, retire);
    commit_together({&a, &old_plots, &users});
  }
  EXPECT_EQ(test::file_text(manifest), "second");
  EXPECT_FALSE(fs::exists(plots)) << "the plots of the manifest replaced";
  EXPECT_EQ(test::file_text(mine + "/mine.txt"), "precious") << "not haptex's: left alone";
  EXPECT_TRUE(temporaries_of(plots).empty());
}

// --force swaps out an earlier file, never a folder that took its name while the run wrote.
TEST(OutputSet, ForceNeverSwapsOutAFolderThatTookTheFilesName) {
  const test::TempDir dir;
  const std::string model = dir.file("m.h5");
  std::ofstream(model) << "old model";
  {
    PartialFile a(model, true);
    write_text(a, "new model");
    fs::remove(model);
    fs::create_directory(model);
    std::ofstream(model + "/mine.txt") << "precious";
    EXPECT_THROW(commit_together({&a}), Error);
  }
  EXPECT_EQ(test::file_text(model + "/mine.txt"), "precious");
  EXPECT_TRUE(temporaries_of(model).empty());
}

// Review 3, #3: SIGTERM between the renames of outputs that belong together (a model and its
// training log) left the model without its log. The signal waits until both are in place, then ends
// the run by itself. A child process takes the signal, as a run would.
TEST(OutputSet, ASignalBetweenRenamesOfASetWaitsForTheWholeSet) {
  const test::TempDir dir;
  const std::string model = dir.file("m.h5"), log = dir.file("m.training.json");
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    remove_temporaries_on_signals();
    PartialFile a(model, false), b(log, false);
    write_text(a, "model"), write_text(b, "log");
    Then a_then_signal(a, [] {
      ::kill(::getpid(), SIGTERM);
      ::usleep(300000);  // time enough for the signal to end the process, were it not held
    });
    commit_together({&a_then_signal, &b});
    ::sleep(10);  // the signal ends it here
    ::_exit(0);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM) << "status " << status;
  EXPECT_EQ(test::file_text(model), "model");
  EXPECT_EQ(test::file_text(log), "log") << "the set was cut between its renames";
  EXPECT_TRUE(temporaries_of(model).empty() && temporaries_of(log).empty());
}

}  // namespace
}  // namespace haptex
