// Issue 32, classes 2 and 17: `capture record --force` replaces only what the old session wrote
// (capture/recording/session_folder.hpp), and session.json's `command` pastes as the same command.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <sys/mount.h>

#include <filesystem>
#include <fstream>
#include <csignal>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include "core/content_mark.hpp"
#include "tests/hostile/hostile_support.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {
namespace fs = std::filesystem;

CommandResult record(const std::string& device, const std::string& out, bool force, const std::string& material = "Cork") {
  std::vector<std::string> args{"capture", "record", "--device", device, "--material", material, "--presses", "1", "-o", out};
  if (force) args.push_back("--force");
  return run_haptex(args);
}

const std::string kFake = "fake:size=160x120,lockstep";

TEST(SessionFolder, ForceKeepsTheReplayedPressFile) {
  const TempDir d;
  const std::string o = d.file("o");
  ASSERT_EQ(record(kFake, o, false).exit_code, 0);
  const std::string press = o + "/press_0.h5", before = file_bytes(press);
  expect_refusal(record("replay:" + press, o, true), {press, "also an input"});
  EXPECT_EQ(file_bytes(press), before);
  EXPECT_TRUE(fs::exists(o + "/session.json"));
}

TEST(SessionFolder, ForceRefusesAFolderHoldingFilesTheSessionDidNotWrite) {
  for (const std::string name : {"press_mycalibration.h5", "notes.txt", "press_7.h5"}) {
    SCOPED_TRACE(name);
    const TempDir d;
    const std::string o = d.file("o");
    ASSERT_EQ(record(kFake, o, false).exit_code, 0);
    std::ofstream(o + "/" + name) << "mine";
    const std::string press = file_bytes(o + "/press_0.h5");
    expect_refusal(record(kFake, o, true), {o, name, "does not list it"});
    EXPECT_EQ(file_bytes(o + "/" + name), "mine");
    EXPECT_EQ(file_bytes(o + "/press_0.h5"), press) << "nothing is deleted before the refusal";
  }
}

TEST(SessionFolder, ForceRefusesASessionJsonHaptexDidNotWrite) {
  const TempDir d;
  const std::string o = d.file("o");
  fs::create_directory(o);
  std::ofstream(o + "/session.json") << R"({"presses": [{"file": "press_0.h5"}]})";
  std::ofstream(o + "/press_0.h5") << "my own";
  expect_refusal(record(kFake, o, true), {"session.json", "capture-session/1"});
  EXPECT_EQ(file_bytes(o + "/press_0.h5"), "my own");
}

// Review 30, F4: another take's press moved in under a name session.json lists is a haptex press file
// too; it was replaced, its only copy lost. session.json records each press's SHA-256.
TEST(SessionFolder, ForceKeepsAnotherTakesPressMovedInUnderAListedName) {
  const TempDir d;
  const std::string foo = d.file("foo"), bar = d.file("bar");
  ASSERT_EQ(record(kFake, foo, false, "Foo").exit_code, 0);
  ASSERT_EQ(record("fake:size=160x120,lockstep,speed=2", bar, false, "Bar").exit_code, 0);
  fs::rename(bar + "/press_0.h5", foo + "/press_0.h5");
  const std::string moved = file_bytes(foo + "/press_0.h5");
  expect_refusal(record(kFake, foo, true, "Foo"), {foo, "press_0.h5", "SHA-256"});
  EXPECT_EQ(file_bytes(foo + "/press_0.h5"), moved);
  EXPECT_EQ(record(kFake, bar, true, "Bar").exit_code, 0) << "a session whose presses are its own is replaced";
}

// Review 21, F6: session.json carried no content mark, so --force replaced one the user had edited.
TEST(SessionFolder, ForceKeepsASessionJsonTheUserEdited) {
  const TempDir d;
  const std::string o = d.file("o");
  ASSERT_EQ(record(kFake, o, false).exit_code, 0);
  nlohmann::json manifest = nlohmann::json::parse(file_bytes(o + "/session.json"));
  manifest["warnings"].push_back("MY NOTES: the gel was scratched");
  const std::string edited = manifest.dump(2);
  {
    std::fstream f(o + "/session.json", std::ios::in | std::ios::out | std::ios::trunc);  // in place: the mark stays, stale
    f << edited;
  }
  expect_refusal(record(kFake, o, true), {"session.json", "is not as haptex wrote it"});
  EXPECT_EQ(file_bytes(o + "/session.json"), edited);
}

// Review 22, F5: on a file system that keeps no extended attributes (ramfs here; NFSv3, vfat and many
// cluster mounts alike) the take refused its own session.json after the first press, for want of the
// mark. The take records every press; --force afterwards keeps the unmarked manifest, as any file haptex
// cannot tell from a user's.
TEST(SessionFolder, ATakeOnAFileSystemWithoutExtendedAttributesRecordsEveryPress) {
  const TempDir d;
  if (::mount("ramfs", d.path().c_str(), "ramfs", MS_NOSUID | MS_NODEV, nullptr) != 0)
    GTEST_SKIP() << "cannot mount a ramfs here (needs root with CAP_SYS_ADMIN)";
  const std::string o = d.file("o");
  const CommandResult r = run_haptex({"capture", "record", "--device", kFake, "--material", "Cork", "--presses", "3", "-o", o, "-q"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json manifest = nlohmann::json::parse(file_bytes(o + "/session.json"));
  EXPECT_EQ(manifest["presses"].size(), 3u) << manifest.dump();
  expect_refusal(record(kFake, o, true), {"session.json", "is not as haptex wrote it"});
  ::umount2(d.path().c_str(), MNT_DETACH);
}

// Review 2, #13: a session of a newer haptex is called that, not "not a capture session's manifest".
// Review 23, F7: the press files a marked session.json lists were matched with std::regex, which
// recurses once per character: a 300 000-digit press file name overflowed the stack (SIGSEGV).
TEST(SessionFolder, ForceReadsAPressFileNameOfAnyLengthWithoutCrashing) {
  const TempDir d;
  const std::string o = d.file("o");
  ASSERT_EQ(record(kFake, o, false).exit_code, 0);
  nlohmann::json doc = nlohmann::json::parse(file_bytes(o + "/session.json"));
  doc["presses"][0]["file"] = "press_" + std::string(300000, '0') + ".h5";
  {
    std::ofstream(o + "/session.json", std::ios::trunc) << doc.dump();
    const int fd = ::open((o + "/session.json").c_str(), O_RDONLY);
    ASSERT_GE(fd, 0);
    mark_content(fd);  // as haptex marks what it writes: the edit is the test's, not a user's
    ::close(fd);
  }
  const std::string press = file_bytes(o + "/press_0.h5");
  expect_refusal(record(kFake, o, true), {o, "press_0.h5", "does not list it"});
  EXPECT_EQ(file_bytes(o + "/press_0.h5"), press);
}

TEST(SessionFolder, ForceRefusesASessionOfANewerHaptex) {
  const TempDir d;
  const std::string o = d.file("o");
  ASSERT_EQ(record(kFake, o, false).exit_code, 0);
  nlohmann::json manifest = nlohmann::json::parse(file_bytes(o + "/session.json"));
  manifest["format"] = "capture-session/2";
  std::ofstream(o + "/session.json") << manifest.dump();
  const std::string press = file_bytes(o + "/press_0.h5");
  expect_refusal(record(kFake, o, true), {"session.json", "capture-session/2", "newer haptex"});
  EXPECT_EQ(file_bytes(o + "/press_0.h5"), press);
}

TEST(SessionFolder, ForceRefusesAListedPressFileHaptexDidNotWrite) {
  const TempDir d;
  const std::string o = d.file("o");
  ASSERT_EQ(record(kFake, o, false).exit_code, 0);
  fs::remove(o + "/press_0.h5");
  std::ofstream(o + "/press_0.h5") << "my own";
  expect_refusal(record(kFake, o, true), {"press_0.h5", "haptex wrote"});
  EXPECT_EQ(file_bytes(o + "/press_0.h5"), "my own");
}

TEST(SessionFolder, ForceReplacesTheOldSession) {
  const TempDir d;
  const std::string o = d.file("o");
  ASSERT_EQ(record(kFake, o, false).exit_code, 0);
  const CommandResult r = record(kFake, o, true, "Felt");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(file_bytes(o + "/session.json"))["material"], "Felt");
}

// Review 8: --force deleted the old session's presses as the take started, so a take that ended before
// its first press (an unplugged sensor, Ctrl-C) left an empty session and the old recordings gone.
TEST(SessionFolder, ForceKeepsTheOldSessionUntilTheNewTakeSavesAPress) {
  const TempDir d;
  const std::string o = d.file("o");
  ASSERT_EQ(record(kFake, o, false).exit_code, 0);
  const std::string old_press = file_bytes(o + "/press_0.h5"), old_manifest = file_bytes(o + "/session.json");
  const CommandResult unplugged = record("fake:size=160x120,lockstep,disconnect=5", o, true, "Felt");
  EXPECT_EQ(unplugged.exit_code, 1) << unplugged.err;
  EXPECT_EQ(file_bytes(o + "/press_0.h5"), old_press);
  EXPECT_EQ(file_bytes(o + "/session.json"), old_manifest);
  const int pid = start_haptex({"capture", "record", "--device", "fake:size=160x120", "--material", "Felt", "-o", o, "--force"});
  ::usleep(500000);  // the fake camera presses after its first seconds
  ::kill(pid, SIGTERM);
  wait_for(pid);
  EXPECT_EQ(file_bytes(o + "/press_0.h5"), old_press);
  EXPECT_EQ(file_bytes(o + "/session.json"), old_manifest);
  EXPECT_EQ(std::distance(fs::directory_iterator(d.path()), fs::directory_iterator()), 1) << "the old session was left aside";
}

// Review 8: a second take into a folder whose take was still recording, with --force, deleted the
// running take's files; the running take then exited 0 with its presses gone.
TEST(SessionFolder, ASecondTakeIntoAFolderBeingRecordedIsRefused) {
  const TempDir d;
  const std::string o = d.file("o");
  const int pid = start_haptex({"capture", "record", "--device", "fake:size=160x120", "--material", "Cork", "-o", o});
  for (int i = 0; i < 200 && !fs::exists(o + "/session.json"); ++i) ::usleep(50000);
  ASSERT_TRUE(fs::exists(o + "/session.json")) << "the first take did not start";
  const std::string manifest = file_bytes(o + "/session.json");
  expect_refusal(record(kFake, o, true, "Felt"), {o, "another haptex take is recording into this folder"});
  EXPECT_TRUE(fs::exists(o + "/session.json"));
  ::kill(pid, SIGTERM);
  wait_for(pid);
  EXPECT_EQ(nlohmann::json::parse(file_bytes(o + "/session.json"))["material"], "Cork");
}

// The recorded command, split as a POSIX shell splits it (shlex), gives back every word: a name with
// quotes, back-quotes or $ stays a name when the line is pasted.
// A press file found inside an input folder is an input: extract never writes over it, by its name or
// a hard link to it, with or without --force (issue 32, review 2).
TEST(SessionFolder, ExtractNeverWritesOverARecordedPress) {
  const TempDir d;
  const std::string session = d.file("sess");
  ASSERT_EQ(record(kFake, session, false).exit_code, 0);
  const std::string press = session + "/press_0.h5", before = file_bytes(press);
  fs::create_hard_link(press, d.file("link.h5"));
  for (const std::string& out : {press, d.file("link.h5")}) {
    SCOPED_TRACE(out);
    expect_refusal(run_haptex({"capture", "extract", session, "-o", out, "--force"}), {"also an input"});
  }
  EXPECT_EQ(file_bytes(press), before);
}

TEST(SessionFolder, TheRecordedCommandPastesAsTheSameCommand) {
  if (!python_has("json")) GTEST_SKIP() << "python3 is not installed";
  const TempDir d;
  const std::string material = "Bob's `touch pwned` $(id) \"felt\"", o = d.file("it's $HOME");
  const CommandResult r = run_haptex({"capture", "record", "--device", kFake, "--material", material, "--presses", "1", "--seconds", "100",
                                      "--pre-frames", "5", "--control", "gain=3", "-o", o});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string command = nlohmann::json::parse(file_bytes(o + "/session.json"))["command"];
  const CommandResult split = run_python({"-c", "import json, shlex, sys; print(json.dumps(shlex.split(sys.argv[1])))", command});
  ASSERT_EQ(split.exit_code, 0) << split.err;
  const nlohmann::json words = nlohmann::json::parse(split.out);
  // Every option given, in the order the command declares them, and the folder.
  const std::vector<std::string> expected{"haptex", "capture", "record", "--device", kFake, "--material", material, "--presses", "1",
                                          "--control", "gain=3", "--seconds", "100", "--pre-frames", "5", "-o", o};
  EXPECT_EQ(words.get<std::vector<std::string>>(), expected) << command;
}

}  // namespace
}  // namespace haptex::test
