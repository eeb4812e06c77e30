// Issue 11 point 2: --force replaces only what haptex wrote, and no command writes over one of its
// inputs (the same file by device and inode), with or without --force.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <fstream>
#include <thread>
#include <chrono>
#include <csignal>
#include <sys/wait.h>

#include "core/sha256.hpp"
#include "core/temporary_name.hpp"
#include "tests/hostile/hostile_support.hpp"
#include "tests/support/mutations.hpp"
#include "tests/support/quick_models.hpp"
#include "tests/support/small_pipeline.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {
namespace fs = std::filesystem;

const std::vector<std::string> kTinySynth = {"synth", "materials", "-n", "1", "--presses", "1", "--recordings", "1",
                                            "--seconds", "0.5", "--size", "64x48"};

std::vector<std::string> tiny_synth(const std::string& out, bool force) {
  std::vector<std::string> args = kTinySynth;
  args.insert(args.end(), {"-o", out});
  if (force) args.push_back("--force");
  return args;
}

TEST(Force, SynthRefusesAFolderHoldingFilesItDidNotWrite) {
  const TempDir dir;
  const std::string out = dir.file("out");
  ASSERT_EQ(run_haptex(tiny_synth(out, false)).exit_code, 0);
  ASSERT_EQ(run_haptex(tiny_synth(out, true)).exit_code, 0) << "its own earlier output is replaced";

  std::ofstream(out + "/notes.txt") << "mine";
  expect_refusal(run_haptex(tiny_synth(out, true)), {out, "notes.txt", "did not write"});
  EXPECT_EQ(file_bytes(out + "/notes.txt"), "mine");
  fs::remove(out + "/notes.txt");

  const fs::path material = *fs::directory_iterator(out + "/gelsight");
  std::ofstream(material / "mine.txt") << "mine too";
  expect_refusal(run_haptex(tiny_synth(out, true)), {"mine.txt"});
  EXPECT_EQ(file_bytes((material / "mine.txt").string()), "mine too");
  EXPECT_EQ(partial_files(dir.path().string()), std::vector<std::string>{});
}

// Review 2, #14: a link inside the folder was named by its target (../../etc/passwd), and a damaged
// file list was reported as a file haptex did not write.
TEST(Force, ALinkOrADamagedFileListInTheFolderIsNamedForWhatItIs) {
  const TempDir dir;
  const std::string out = dir.file("out");
  ASSERT_EQ(run_haptex(tiny_synth(out, false)).exit_code, 0);
  const fs::path material = *fs::directory_iterator(out + "/gelsight");
  const fs::path press = *fs::directory_iterator(material);
  const std::string listed = press.lexically_relative(out).generic_string(), kept = file_bytes(press.string());
  fs::rename(press, dir.file("moved"));
  fs::create_symlink("/etc/passwd", press);
  expect_refusal(run_haptex(tiny_synth(out, true)), {out + ": " + listed, "symbolic link"});
  EXPECT_TRUE(fs::is_symlink(press));
  fs::remove(press);
  fs::rename(dir.file("moved"), press);
  const std::string list = file_bytes(out + "/haptex-files.json");
  std::ofstream(out + "/haptex-files.json") << "{\"files\": [1e400]}";
  expect_refusal(run_haptex(tiny_synth(out, true)), {out, "haptex-files.json cannot be read", "1e400"});
  EXPECT_EQ(file_bytes(press.string()), kept);
}

// Review 3: --force judged a folder's files by their names alone, so a user's own truth.h5 (or one
// edited since) with a listed name was deleted. The list now holds each file's SHA-256.
TEST(Force, AListedFileThatIsNotTheOneHaptexWroteIsKept) {
  const TempDir dir;
  const std::string out = dir.file("out");
  ASSERT_EQ(run_haptex(tiny_synth(out, false)).exit_code, 0);
  std::ofstream(out + "/truth.h5") << "my own truth";
  expect_refusal(run_haptex(tiny_synth(out, true)), {out, "truth.h5", "not the one haptex wrote"});
  EXPECT_EQ(file_bytes(out + "/truth.h5"), "my own truth");
}

TEST(Force, SynthRefusesAFolderWithoutItsFileList) {
  const TempDir dir;
  fs::create_directory(dir.file("mine"));
  std::ofstream(dir.file("mine/data.csv")) << "1,2\n";
  expect_refusal(run_haptex(tiny_synth(dir.file("mine"), true)), {"haptex-files.json"});
  EXPECT_EQ(file_bytes(dir.file("mine/data.csv")), "1,2\n");
}

TEST(Force, EvaluateRefusesAReportFolderHoldingAFileOfYours) {
  const TempDir dir;
  const SmallPipeline& p = small_pipeline();
  const std::vector<std::string> args = {"evaluate", p.dataset, "--split", p.split, "--model", quick_model(), "--repeats", "2",
                                         "--reconstruct", "none", "-o", dir.file("report"), "--force"};
  ASSERT_EQ(run_haptex(args).exit_code, 0);
  std::ofstream(dir.file("report/my_notes.md")) << "notes";
  expect_refusal(run_haptex(args), {"my_notes.md"});
  EXPECT_EQ(file_bytes(dir.file("report/my_notes.md")), "notes");
}

// Review 14, F3: evaluate judged its report folder only after the whole evaluation. Given a model file
// that is no model, each of these is refused naming the folder, so before any input was read.
TEST(Force, EvaluateRefusesAReportFolderItCannotWriteBeforeAnyWork) {
  const TempDir inputs, dir;
  const SmallPipeline& p = small_pipeline();
  std::ofstream(inputs.file("broken.h5")) << "no model";
  fs::create_directories(dir.file("mine"));
  std::ofstream(dir.file("mine/notes.txt")) << "mine";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {dir.file("nodir/rep"), "does not exist"}, {".", "not a name"}, {dir.file("mine"), "haptex-files.json"}};
  for (const auto& [output, says] : cases) {
    SCOPED_TRACE(output);
    // Run in dir, so "." is a folder holding no input.
    expect_refusal(run_program({haptex_binary(), "evaluate", p.dataset, "--split", p.split, "--model", inputs.file("broken.h5"), "-o", output,
                                "--force"},
                               dir.path().string()),
                   {output, says});
  }
  EXPECT_EQ(file_bytes(dir.file("mine/notes.txt")), "mine");
}

// Each command, given one of its inputs as output (by name, through a symbolic or a hard link),
// refuses with or without --force and leaves the input as it was.
struct SameFileCase {
  std::string name;
  std::function<std::vector<std::string>(const TempDir&)> args;  // the output is dir/"victim"
  std::string victim_source;                                     // the file the victim starts as
};

TEST(Force, NoCommandWritesOverItsInput) {
  const SmallPipeline& p = small_pipeline();
  const TempDir synth_dir;
  ASSERT_EQ(run_haptex(tiny_synth(synth_dir.file("s"), false)).exit_code, 0);
  const std::string xml = (*fs::directory_iterator(synth_dir.file("s/recordings"))).path().string();
  const std::vector<SameFileCase> cases = {
      {"convert", [](const TempDir& d) { return std::vector<std::string>{"convert", "hatt", d.file("victim"), "-o", d.file("victim")}; }, xml},
      {"align", [&](const TempDir& d) { return std::vector<std::string>{"align", "--recordings", d.file("victim"), "--gelsight", p.gelsight, "-o", d.file("victim")}; }, p.recordings},
      {"split", [](const TempDir& d) { return std::vector<std::string>{"split", d.file("victim"), "-o", d.file("victim"), "--no-plots"}; }, p.dataset},
      {"train", [&](const TempDir& d) { return quick_train_args(p.dataset, d.file("victim"), d.file("victim")); }, p.split},
      {"render", [&](const TempDir& d) {
         std::ofstream(d.file("victim")) << "force,speed\n1,100\n";
         return std::vector<std::string>{"render", quick_model(), "--material", "any", "--trajectory", d.file("victim"),
                                         "-o", d.file("out.wav"), "--csv", d.file("victim")};
       }, ""},
      {"windows", [&](const TempDir& d) { return std::vector<std::string>{"windows", d.file("victim"), "--split", p.split, "-o", d.file("victim")}; }, p.dataset},
      {"extract", [](const TempDir& d) { return std::vector<std::string>{"capture", "extract", d.file("victim"), "-o", d.file("victim")}; }, p.gelsight},
      {"merge", [&](const TempDir& d) { return std::vector<std::string>{"merge", p.gelsight, d.file("victim"), "-o", d.file("victim")}; }, p.gelsight},
  };
  for (const SameFileCase& c : cases) {
    for (const char* how : {"name", "symlink", "hardlink"}) {
      for (bool force : {false, true}) {
        SCOPED_TRACE(c.name + std::string(" via ") + how + (force ? " --force" : ""));
        const TempDir d;
        std::vector<std::string> args = c.args(d);
        if (!c.victim_source.empty()) fs::copy_file(c.victim_source, d.file("victim"));
        const std::string before = file_bytes(d.file("victim"));
        if (std::string(how) != "name") {
          // The output names the input through a link.
          std::string& output = *std::find(args.rbegin(), args.rend(), d.file("victim"));
          if (std::string(how) == "symlink") fs::create_symlink(d.file("victim"), d.file("link"));
          else fs::create_hard_link(d.file("victim"), d.file("link"));
          output = d.file("link");
        }
        if (force) args.push_back("--force");
        expect_refusal(run_haptex(args), {"is also an input"});
        EXPECT_EQ(file_bytes(d.file("victim")), before);
        EXPECT_EQ(partial_files(d.path().string()), std::vector<std::string>{});
      }
    }
  }
}

// --force replaces only what haptex wrote: every command writing an HDF5 file leaves a user's file of
// the same name alone (core/h5/atomic_file.hpp), and replaces its own.
TEST(Force, NoCommandReplacesAFileHaptexDidNotWrite) {
  const SmallPipeline& p = small_pipeline();
  const TempDir synth_dir;
  ASSERT_EQ(run_haptex(tiny_synth(synth_dir.file("s"), false)).exit_code, 0);
  const std::vector<std::pair<std::string, std::vector<std::string>>> commands = {
      {"convert", {"convert", "hatt", synth_dir.file("s/recordings")}},
      {"align", {"align", "--recordings", p.recordings, "--gelsight", p.gelsight}},
      {"windows", {"windows", p.dataset, "--split", p.split}},
      {"merge", {"merge", p.gelsight}},
  };
  for (const auto& [name, command] : commands) {
    SCOPED_TRACE(name);
    const TempDir d;
    std::ofstream(d.file("out.h5")) << "my own notes";
    std::vector<std::string> args = command;
    args.insert(args.end(), {"-o", d.file("out.h5"), "--force"});
    expect_refusal(run_haptex(args), {"--force replaces only a file haptex wrote"});
    EXPECT_EQ(file_bytes(d.file("out.h5")), "my own notes");
    fs::remove(d.file("out.h5"));
    ASSERT_EQ(run_haptex(args).exit_code, 0) << "a new file";
    EXPECT_EQ(run_haptex(args).exit_code, 0) << "and its own, replaced";
  }
}

// A WAV of the user's: a valid RIFF header and silence, with no software string.
void write_foreign_wav(const std::string& path) {
  std::string wav = "RIFF", body;
  const auto u32 = [](std::string& s, std::uint32_t v) { for (int i = 0; i < 4; ++i) s += char((v >> (8 * i)) & 0xff); };
  const auto u16 = [](std::string& s, std::uint16_t v) { s += char(v & 0xff); s += char(v >> 8); };
  body = "WAVEfmt ";
  u32(body, 16), u16(body, 1), u16(body, 1), u32(body, 8000), u32(body, 16000), u16(body, 2), u16(body, 16);
  body += "data";
  u32(body, 200);
  body += std::string(200, '\0');
  u32(wav, std::uint32_t(body.size()));
  std::ofstream(path, std::ios::binary) << wav << body;
}

// Issue 32, class 3: the commands whose output is text (JSON, CSV) or sound replace, with --force, only
// a file of that kind haptex wrote (docs/architecture.md, "Outputs are atomic"): never an HDF5 file, a
// CSV, a JSON or a WAV of the user's.
TEST(Force, NoTextOutputReplacesAFileHaptexDidNotWrite) {
  const SmallPipeline& p = small_pipeline();
  const TempDir d;
  std::ofstream(d.file("traj.csv")) << "time_s,force_n,speed_mm_s\n0,1,50\n0.01,1,50\n0.02,1,50\n";
  const std::string hdf5 = copy_into(d, p.recordings, "mine.h5");
  std::ofstream(d.file("mine.csv")) << "a,b\n1,2\n";
  std::ofstream(d.file("mine.json")) << R"({"format": "notes/1", "text": "mine"})";
  write_foreign_wav(d.file("mine.wav"));
  const auto commands = [&](const std::string& victim) {
    return std::vector<std::pair<std::string, std::vector<std::string>>>{
        {"split", {"split", p.dataset, "-o", victim, "--no-plots", "--force"}},
        {"train --log", {"train", p.dataset, "--split", p.split, "-o", d.file("m.h5"), "--log", victim, "--force"}},
        {"render -o", {"render", quick_model(), "--material", small_material(), "--trajectory", d.file("traj.csv"), "-o", victim, "--force"}},
        {"render --csv", {"render", quick_model(), "--material", small_material(), "--trajectory", d.file("traj.csv"), "-o",
                          d.file("v.wav"), "--csv", victim, "--force"}},
    };
  };
  for (const std::string& victim : {hdf5, d.file("mine.csv"), d.file("mine.json"), d.file("mine.wav")}) {
    for (const auto& [name, command] : commands(victim)) {
      SCOPED_TRACE(name + " over " + victim);
      const std::string before = file_bytes(victim);
      expect_refusal(run_haptex(command), {victim, "--force replaces only"});
      EXPECT_EQ(file_bytes(victim), before);
    }
  }
  EXPECT_FALSE(fs::exists(d.file("m.h5")));
  EXPECT_FALSE(fs::exists(d.file("v.wav")));
}

TEST(Force, TextOutputsReplaceTheirOwn) {
  const SmallPipeline& p = small_pipeline();
  const TempDir d;
  {
    std::ofstream trajectory(d.file("traj.csv"));
    trajectory << "force,speed\n";
    for (int i = 0; i < 4000; ++i) trajectory << "1,100\n";
  }
  const std::vector<std::vector<std::string>> commands = {
      {"split", p.dataset, "-o", d.file("s.json"), "--no-plots", "--force"},
      {"render", quick_model(), "--material", small_material(), "--trajectory", d.file("traj.csv"), "-o", d.file("v.wav"),
       "--csv", d.file("v.csv"), "--force"},
  };
  for (const auto& command : commands) {
    SCOPED_TRACE(command.front());
    const CommandResult first = run_haptex(command);
    ASSERT_EQ(first.exit_code, 0) << first.err;
    const CommandResult again = run_haptex(command);
    EXPECT_EQ(again.exit_code, 0) << again.err;
  }
}

// Review 15, R10: --force took the documented header or "format" field as haptex's mark, so a user's
// own trajectory in the documented format, or a haptex output edited since, was replaced. The mark is
// now the SHA-256 of what haptex wrote (core/content_mark.hpp).
TEST(Force, AFileInHaptexsFormatThatHaptexDidNotWriteOrThatWasEditedIsKept) {
  const SmallPipeline& p = small_pipeline();
  const TempDir d;
  const std::vector<std::string> trajectory = {"trajectory", p.dataset, "--material", small_material(), "--seconds", "1", "-o",
                                               d.file("t.csv"), "-q"};
  const std::vector<std::string> split = {"split", p.dataset, "-o", d.file("s.json"), "--no-plots", "-q"};
  std::ofstream(d.file("t.csv")) << "time_s,force_n,speed_mm_s\n0,1,50\n0.5,2,80\n";  // the user's own stroke
  const auto with_force = [](std::vector<std::string> args) {
    args.push_back("--force");
    return args;
  };
  std::string before = file_bytes(d.file("t.csv"));
  expect_refusal(run_haptex(with_force(trajectory)), {d.file("t.csv"), "its bytes are not those haptex wrote", "user.haptex.sha256"});
  EXPECT_EQ(file_bytes(d.file("t.csv")), before);
  fs::remove(d.file("t.csv"));
  for (const std::vector<std::string>& command : {trajectory, split}) {
    SCOPED_TRACE(command.front());
    ASSERT_EQ(run_haptex(command).exit_code, 0);
    ASSERT_EQ(run_haptex(with_force(command)).exit_code, 0) << "haptex's own, unchanged, is replaced";
    const std::string output = command[command.size() - (command.front() == "split" ? 3 : 2)];
    std::ofstream(output, std::ios::app) << (command.front() == "split" ? " " : "1,1,1\n");  // an edit
    before = file_bytes(output);
    expect_refusal(run_haptex(with_force(command)), {output, "its bytes are not those haptex wrote"});
    EXPECT_EQ(file_bytes(output), before);
  }
}

// Review 2, #12 and #13: --force replaced a haptex output of another kind (train over a gelsight
// file) or of a newer haptex (model/4, split/2) silently, and called a newer JSON output "not one".
// Now it replaces only an earlier output of the kind it writes, and says which rule the file breaks.
TEST(Force, OnlyAnEarlierOutputOfTheSameKindIsReplaced) {
  const SmallPipeline& p = small_pipeline();
  const TempDir d;
  const std::string newer_model = copy_into(d, quick_model(), "newer.h5"), gelsight = copy_into(d, p.gelsight, "g.h5"),
                    recordings = copy_into(d, p.recordings, "r.h5");
  Edit(newer_model).root().set_attr("haptex_format", "model/99");
  std::ofstream(d.file("log.json")) << R"({"format": "training-log/1"})";
  std::ofstream(d.file("newer_split.json")) << R"({"format": "split/2"})";
  std::ofstream(d.file("newer_log.json")) << R"({"format": "training-log/2"})";
  const std::vector<std::pair<std::vector<std::string>, std::vector<std::string>>> refused = {
      {{"train", p.dataset, "--split", p.split, "-o", newer_model, "--per-material", "--force"}, {newer_model, "model/99", "newer haptex"}},
      {{"train", p.dataset, "--split", p.split, "-o", gelsight, "--force"}, {gelsight, "is a gelsight/2 file", "same kind"}},
      {{"merge", p.gelsight, "-o", recordings, "--force"}, {recordings, "is a recordings/", "writes gelsight/2"}},
      {{"split", p.dataset, "-o", d.file("log.json"), "--no-plots", "--force"}, {d.file("log.json"), "is a training-log/1 file"}},
      {{"split", p.dataset, "-o", d.file("newer_split.json"), "--no-plots", "--force"}, {"split/2", "newer haptex"}},
      {{"train", p.dataset, "--split", p.split, "-o", d.file("m.h5"), "--log", d.file("newer_log.json"), "--force"},
       {"training-log/2", "newer haptex"}},
  };
  for (const auto& [command, says] : refused) {
    SCOPED_TRACE(command.front() + ": " + says.front());
    const std::vector<std::string> before = {file_bytes(newer_model), file_bytes(gelsight), file_bytes(recordings)};
    expect_refusal(run_haptex(command), says);
    EXPECT_EQ(before, (std::vector<std::string>{file_bytes(newer_model), file_bytes(gelsight), file_bytes(recordings)}));
  }
  EXPECT_FALSE(fs::exists(d.file("m.h5")));
  // Review 6: a mark no haptex writes ("recordings/-1", "recordings/01") passed as an earlier version.
  for (const std::string mark : {"recordings/-1", "recordings/01", "recordings/0"}) {
    SCOPED_TRACE(mark);
    const std::string odd = copy_into(d, p.recordings, "odd.h5");
    Edit(odd).root().set_attr("haptex_format", mark);
    const std::string before = file_bytes(odd);
    expect_refusal(run_haptex({"merge", p.recordings, "-o", odd, "--force"}), {odd, "is a " + mark + " file", "same kind"});
    EXPECT_EQ(file_bytes(odd), before);
  }
}

// Review 5: --force checked an earlier training log as haptex's before the training only; a file of
// the user's that took its place meanwhile was replaced at the end. It is checked again at the swap.
TEST(Force, AFileThatTakesTheOutputsPlaceDuringTheRunIsKept) {
  const TempDir d;
  const std::string model = d.file("m.h5"), log = d.file("m.training.json"), progress = d.file("progress.txt");
  std::vector<std::string> args = {"train", small_pipeline().dataset, "--split", small_pipeline().split, "-o", model,
                                   "--epochs", "100", "--latent", "8", "--hidden", "16", "-v"};
  ASSERT_EQ(run_haptex(args).exit_code, 0);  // haptex's model and log, which --force may replace
  const std::string earlier_model = file_bytes(model);
  args.push_back("--force");
  const int pid = start_haptex(args, "/dev/null", progress);
  while (file_bytes(progress).find("epoch") == std::string::npos && file_bytes(progress).find("error") == std::string::npos)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  std::ofstream(log) << "the user's notes";  // the training has dozens of epochs to go
  const int status = wait_for(pid);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2) << file_bytes(progress);
  EXPECT_NE(file_bytes(progress).find(log + ": --force replaces only"), std::string::npos) << file_bytes(progress);
  EXPECT_EQ(file_bytes(log), "the user's notes");
  EXPECT_EQ(file_bytes(model), earlier_model);  // the model appears with its log or not at all
  EXPECT_TRUE(partial_files(d.path().string()).empty());
}

// Review 5: split --force checked its earlier manifest as haptex's before the work only, so a file of
// the user's that took its place while the run wrote was replaced. The run is stopped while its plot
// folder is still a temporary (so the manifest is not yet in place), the file is swapped, and it goes on.
TEST(Force, SplitKeepsAFileThatTookTheManifestsPlaceDuringTheRun) {
  const TempDir d;
  const std::string manifest = d.file("s.json"), plots = d.file("s.plots"), err = d.file("err.txt");
  const std::vector<std::string> args = {"split", small_pipeline().dataset, "-o", manifest, "--force"};
  ASSERT_EQ(run_haptex(args).exit_code, 0);  // haptex's manifest, which --force may replace
  bool swapped = false;
  for (int attempt = 0; attempt < 20 && !swapped; ++attempt) {
    const int pid = start_haptex(args, "/dev/null", err);
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (temporaries_of(plots).empty() && ::waitpid(pid, nullptr, WNOHANG) == 0 && std::chrono::steady_clock::now() < give_up) {
    }
    if (::kill(pid, SIGSTOP) == 0 && !temporaries_of(plots).empty()) {
      std::ofstream(manifest) << "the user's notes";
      swapped = true;
    }
    ::kill(pid, SIGCONT);
    const int status = wait_for(pid);
    if (!swapped) continue;  // the run finished before it was caught: again
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 2) << file_bytes(err);
    EXPECT_NE(file_bytes(err).find(manifest + ": "), std::string::npos) << file_bytes(err);
    EXPECT_EQ(file_bytes(manifest), "the user's notes");
    EXPECT_TRUE(temporaries_of(plots).empty());
    EXPECT_TRUE(temporaries_of(manifest).empty());
  }
  EXPECT_TRUE(swapped) << "no run of split was caught while it wrote";
}

TEST(Force, TrainRefusesALogThatIsTheModel) {
  const TempDir dir;
  std::vector<std::string> args = quick_train_args(small_pipeline().dataset, small_pipeline().split, dir.file("m.h5"));
  args.insert(args.end(), {"--log", dir.file("./m.h5")});
  expect_refusal(run_haptex(args), {"--log names the model file itself"});
  EXPECT_FALSE(std::filesystem::exists(dir.file("m.h5")));
}

// Two outputs of one command named by two spellings of one relative path ("x.wav", "./x.wav") are
// refused as one file, not as "another run is writing" (issue 32, review 2).
TEST(Force, TwoSpellingsOfOneRelativeOutputAreOneFile) {
  const TempDir dir;
  {
    std::ofstream trajectory(dir.file("traj.csv"));
    trajectory << "force,speed\n";
    for (int i = 0; i < 1000; ++i) trajectory << "1,100\n";
  }
  expect_refusal(run_haptex_in(dir.path().string(), {"render", quick_model(), "--material", small_material(), "--trajectory", "traj.csv",
                                                     "-o", "x.wav", "--csv", "./x.wav"}),
                 {"--csv and -o name the same file"});
  std::vector<std::string> args = quick_train_args(small_pipeline().dataset, small_pipeline().split, "m.h5");
  args.insert(args.end(), {"--log", "./m.h5"});
  expect_refusal(run_haptex_in(dir.path().string(), args), {"--log names the model file itself"});
  EXPECT_FALSE(std::filesystem::exists(dir.file("m.h5")));
  EXPECT_FALSE(std::filesystem::exists(dir.file("x.wav")));
}

TEST(Force, EvaluateRefusesAReportFolderHoldingItsDataset) {
  const TempDir dir;
  const SmallPipeline& p = small_pipeline();
  fs::create_directory(dir.file("work"));
  const std::string dataset = copy_into(dir, p.dataset, "work/d.h5");
  const std::string before = sha256_file(dataset);
  expect_refusal(run_haptex({"evaluate", dataset, "--split", p.split, "--model", quick_model(), "-o", dir.file("work"), "--force"}),
                 {"holds an input"});
  EXPECT_EQ(sha256_file(dataset), before);
}

// Issue 32, class 4: split's plot folder is written whole (core/partial_directory.hpp): a PNG of the
// user's in an existing folder is kept, with --force or without, and the folder split wrote is replaced.
TEST(Force, SplitKeepsAPlotOfTheUsers) {
  const SmallPipeline& p = small_pipeline();
  const TempDir d;
  const std::string manifest = d.file("s.json"), plots = d.file("s.plots");
  fs::create_directory(plots);
  const std::string mine = plots + "/" + material_ids(p.dataset).front() + ".png";
  std::ofstream(mine) << "my figure";
  for (const bool force : {false, true}) {
    std::vector<std::string> args{"split", p.dataset, "-o", manifest};
    if (force) args.push_back("--force");
    expect_refusal(run_haptex(args), {plots});
    EXPECT_EQ(file_bytes(mine), "my figure");
    EXPECT_FALSE(fs::exists(manifest)) << "refused before any work";
  }
  fs::remove_all(plots);
  ASSERT_EQ(run_haptex({"split", p.dataset, "-o", manifest}).exit_code, 0);
  EXPECT_TRUE(fs::exists(plots + "/haptex-files.json"));
  const CommandResult again = run_haptex({"split", p.dataset, "-o", manifest, "--force"});
  EXPECT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(partial_files(d.path().string()), std::vector<std::string>{});
}

// Review 9, C6: a plot folder that is a link to another split's was refused as "not a folder" or as
// holding "what haptex did not write"; the reason is the link.
TEST(Force, SplitCallsALinkedPlotFolderALink) {
  const SmallPipeline& p = small_pipeline();
  const TempDir d;
  ASSERT_EQ(run_haptex({"split", p.dataset, "-o", d.file("other.json")}).exit_code, 0);
  ASSERT_EQ(run_haptex({"split", p.dataset, "-o", d.file("s.json"), "--no-plots"}).exit_code, 0);
  fs::create_directory_symlink("other.plots", d.file("s.plots"));
  const std::string before = file_bytes(d.file("s.json"));
  for (const bool plots : {true, false}) {
    SCOPED_TRACE(plots ? "with plots" : "--no-plots");
    std::vector<std::string> args{"split", p.dataset, "-o", d.file("s.json"), "--force"};
    if (!plots) args.push_back("--no-plots");
    expect_refusal(run_haptex(args), {d.file("s.plots"), "symbolic link", "Remove the link"});
    EXPECT_EQ(file_bytes(d.file("s.json")), before);
    EXPECT_TRUE(fs::is_symlink(d.file("s.plots")));
    EXPECT_TRUE(fs::exists(d.file("other.plots/haptex-files.json")));
  }
}

// --force replaces a folder only of the command that wrote it: split's plots never replace a synth
// output that happens to be named like them (issue 32, review 2).
TEST(Force, SplitNeverReplacesAnotherCommandsFolder) {
  const TempDir d;
  const std::string plots = d.file("z.plots");
  fs::create_directory(plots);
  std::ofstream(plots + "/truth.h5") << "synthetic truth";
  std::ofstream(plots + "/haptex-files.json") << R"({"written_by": "haptex synth", "files": ["truth.h5"]})";
  expect_refusal(run_haptex({"split", small_pipeline().dataset, "-o", d.file("z.json"), "--force"}),
                 {plots, "haptex synth wrote it, not haptex split"});
  EXPECT_EQ(file_bytes(plots + "/truth.h5"), "synthetic truth");
}

// --force --no-plots: the earlier split's plots describe the manifest replaced, so they go; a folder of
// the user's of that name stays (issue 32, review 2).
// Review 33, F1: --force took a companion at the default name that the output it replaced never wrote:
// the log of a model moved away (its only record of training), the plots or sheets of a manifest or a
// gelsight file moved away. A companion at the default name goes only while the output replaced is
// there and names it back; else it stays, or --no-plots/--no-sheets is refused before any work.
TEST(Force, ACompanionOfAnOutputMovedAwayStays) {
  const SmallPipeline& p = small_pipeline();
  const TempDir d;
  std::vector<std::string> train = quick_train_args(p.dataset, p.split, d.file("m.h5"));
  ASSERT_EQ(run_haptex(train).exit_code, 0);
  const std::string log = file_bytes(d.file("m.training.json"));
  fs::rename(d.file("m.h5"), d.file("m_v1.h5"));
  train.insert(train.end(), {"--log", d.file("l.json"), "--force"});
  ASSERT_EQ(run_haptex(train).exit_code, 0);
  EXPECT_EQ(file_bytes(d.file("m.training.json")), log) << "m_v1.h5's log";

  ASSERT_EQ(run_haptex({"split", p.dataset, "-o", d.file("s.json")}).exit_code, 0);
  const std::string plots = file_bytes(d.file("s.plots/haptex-files.json"));
  fs::rename(d.file("s.json"), d.file("s_v1.json"));
  expect_refusal(run_haptex({"split", p.dataset, "-o", d.file("s.json"), "--force", "--no-plots"}), {d.file("s.plots"), "the plot folder"});
  EXPECT_EQ(file_bytes(d.file("s.plots/haptex-files.json")), plots);

  const std::string videos = (fs::path(p.recordings).parent_path() / "synth" / "gelsight" / "Woven 1").string();
  ASSERT_EQ(run_haptex({"capture", "extract", videos, "-o", d.file("g.h5"), "-q"}).exit_code, 0);
  const std::string sheets = file_bytes(d.file("g_sheets/haptex-files.json"));
  fs::rename(d.file("g.h5"), d.file("g_v1.h5"));
  expect_refusal(run_haptex({"capture", "extract", videos, "-o", d.file("g.h5"), "--force", "--no-sheets", "-q"}),
                 {d.file("g_sheets"), "the contact sheet folder"});
  EXPECT_EQ(file_bytes(d.file("g_sheets/haptex-files.json")), sheets);
}

TEST(Force, SplitWithoutPlotsTakesAwayTheEarlierOnes) {
  const SmallPipeline& p = small_pipeline();
  const TempDir d;
  ASSERT_EQ(run_haptex({"split", p.dataset, "-o", d.file("s.json")}).exit_code, 0);
  ASSERT_TRUE(fs::exists(d.file("s.plots")));
  ASSERT_EQ(run_haptex({"split", p.dataset, "-o", d.file("s.json"), "--force", "--no-plots"}).exit_code, 0);
  EXPECT_FALSE(fs::exists(d.file("s.plots")));
  // Review 8: a plot folder --force cannot take away (a file of the user's in it) stayed, silently,
  // beside a manifest it no longer described. It is refused before any work.
  ASSERT_EQ(run_haptex({"split", p.dataset, "-o", d.file("s.json"), "--force"}).exit_code, 0);
  std::ofstream(d.file("s.plots/mine.png")) << "my figure";
  const std::string manifest = file_bytes(d.file("s.json"));
  expect_refusal(run_haptex({"split", p.dataset, "-o", d.file("s.json"), "--force", "--no-plots", "--seed", "7"}),
                 {d.file("s.plots"), "the plot folder", "no longer describes"});
  EXPECT_EQ(file_bytes(d.file("s.plots/mine.png")), "my figure");
  EXPECT_EQ(file_bytes(d.file("s.json")), manifest);
}

TEST(Force, ExtractWithoutSheetsRefusesOldSheetsItCannotTakeAway) {
  const TempDir d;
  const std::string videos = (fs::path(small_pipeline().recordings).parent_path() / "synth" / "gelsight" / "Woven 1").string();
  ASSERT_EQ(run_haptex({"capture", "extract", videos, "-o", d.file("g.h5")}).exit_code, 0);
  std::ofstream(d.file("g_sheets/notes.txt")) << "my notes";
  expect_refusal(run_haptex({"capture", "extract", videos, "-o", d.file("g.h5"), "--force", "--no-sheets"}),
                 {d.file("g_sheets"), "the contact sheet folder"});
  EXPECT_EQ(file_bytes(d.file("g_sheets/notes.txt")), "my notes");
  // Review 9, F6: sheets written elsewhere left the earlier default ones beside the file they no longer describe.
  expect_refusal(run_haptex({"capture", "extract", videos, "-o", d.file("g.h5"), "--force", "--sheets", d.file("other")}),
                 {d.file("g_sheets"), "the contact sheet folder"});
  fs::remove(d.file("g_sheets/notes.txt"));
  ASSERT_EQ(run_haptex({"capture", "extract", videos, "-o", d.file("g.h5"), "--force", "--sheets", d.file("other")}).exit_code, 0);
  EXPECT_FALSE(fs::exists(d.file("g_sheets"))) << "the earlier sheets describe a file now replaced";
  EXPECT_TRUE(fs::is_directory(d.file("other")));
  ASSERT_EQ(run_haptex({"capture", "extract", videos, "-o", d.file("g.h5"), "--force", "--sheets", d.file("./g_sheets")}).exit_code, 0);
  EXPECT_TRUE(fs::is_directory(d.file("g_sheets"))) << "sheets given at the default place are written there";
}

// split, a `gnuplot` first on PATH that puts a file of the user's into the plot folder while the
// plots are drawn (review 4, 3a and 3b: the manifest was renamed into place, then the plots refused).
CommandResult split_while_a_plot_folder_appears(const TempDir& d, std::vector<std::string> args) {
  fs::create_directory(d.file("bin"));
  const std::string plots = d.file("s.plots");
  std::ofstream(d.file("bin/gnuplot")) << "#!/bin/sh\nmkdir -p '" << plots << "' && echo precious > '" << plots
                                       << "/mine.txt'\nexec /usr/bin/gnuplot \"$@\"\n";
  fs::permissions(d.file("bin/gnuplot"), fs::perms::owner_all);
  args.insert(args.begin(), {"env", "PATH=" + d.file("bin") + ":/usr/bin:/bin", haptex_binary(), "split", small_pipeline().dataset, "-o",
                             d.file("s.json")});
  return run_program(args);
}

TEST(Force, AManifestAppearsWithItsPlotsOrNotAtAll) {
  const TempDir d;
  expect_refusal(split_while_a_plot_folder_appears(d, {}), {d.file("s.plots"), "not empty"});
  EXPECT_FALSE(fs::exists(d.file("s.json"))) << "a manifest without its plots";
  EXPECT_EQ(file_bytes(d.file("s.plots/mine.txt")), "precious\n");
  fs::remove_all(d.file("s.plots"));
  ASSERT_EQ(run_haptex({"split", small_pipeline().dataset, "-o", d.file("s.json")}).exit_code, 0);
  const std::string manifest = file_bytes(d.file("s.json"));
  expect_refusal(split_while_a_plot_folder_appears(d, {"--force", "--seed", "5"}), {d.file("s.plots"), "mine.txt"});
  EXPECT_EQ(file_bytes(d.file("s.json")), manifest) << "the earlier manifest, which the plots there describe";
  EXPECT_EQ(partial_files(d.path().string()), std::vector<std::string>{});
}

// --force without sheets or --explain: the folders an earlier extraction wrote describe the file
// replaced, so they go; train --force --log elsewhere: the replaced model's log goes (review 4, 12).
TEST(Force, CompanionsOfAReplacedOutputGoWithIt) {
  const SmallPipeline& p = small_pipeline();
  const TempDir d;
  const std::string videos = (fs::path(p.recordings).parent_path() / "synth" / "gelsight").string();
  ASSERT_EQ(run_haptex({"capture", "extract", videos, "-o", d.file("g.h5"), "--explain", "-q"}).exit_code, 0);
  ASSERT_TRUE(fs::exists(d.file("g_sheets")) && fs::exists(d.file("g_explain")));
  ASSERT_EQ(run_haptex({"capture", "extract", videos + "/Woven 1", "-o", d.file("g.h5"), "--no-sheets", "--force", "-q"}).exit_code, 0);
  EXPECT_FALSE(fs::exists(d.file("g_sheets")));
  EXPECT_FALSE(fs::exists(d.file("g_explain")));
  ASSERT_EQ(run_haptex(quick_train_args(p.dataset, p.split, d.file("m.h5"))).exit_code, 0);
  ASSERT_TRUE(fs::exists(d.file("m.training.json")));
  std::vector<std::string> again = quick_train_args(p.dataset, p.split, d.file("m.h5"));
  again.insert(again.end(), {"--force", "--log", d.file("other.json")});
  ASSERT_EQ(run_haptex(again).exit_code, 0);
  EXPECT_FALSE(fs::exists(d.file("m.training.json"))) << "the log of the model replaced";
  EXPECT_TRUE(fs::exists(d.file("other.json")));
}

// Review 27, F2: companions written under a chosen name (--sheets shx, --log a.json) were kept beside
// the output that replaced theirs. The replaced output names them and the SHA-256 they were written
// with (a gelsight file's contact_sheets and the hash of their haptex-files.json, a model's
// training_log and the log's hash): those go, while a folder holding a file of the user's, or a
// companion another run wrote since at that name, stays.
TEST(Force, CompanionsAtChosenNamesGoWithTheirOutput) {
  const SmallPipeline& p = small_pipeline();
  const TempDir d;
  const std::string videos = (fs::path(p.recordings).parent_path() / "synth" / "gelsight").string(), woven = videos + "/Woven 1";
  const auto extract = [&](const std::string& input, const std::string& output, std::vector<std::string> more) {
    std::vector<std::string> args{"capture", "extract", input, "-o", d.file(output), "-q"};
    args.insert(args.end(), more.begin(), more.end());
    return run_haptex(args).exit_code;
  };
  ASSERT_EQ(extract(videos, "g.h5", {"--sheets", d.file("shx")}), 0);
  ASSERT_EQ(extract(woven, "g.h5", {"--force"}), 0);
  EXPECT_FALSE(fs::exists(d.file("shx"))) << "the replaced file's sheets";
  EXPECT_TRUE(fs::exists(d.file("g_sheets")));
  ASSERT_EQ(extract(videos, "g.h5", {"--force", "--sheets", d.file("shy")}), 0);
  EXPECT_FALSE(fs::exists(d.file("g_sheets"))) << "the default-named sheets of the file replaced";
  std::ofstream(d.file("shy/mine.txt")) << "precious\n";
  ASSERT_EQ(extract(woven, "g.h5", {"--force", "--no-sheets"}), 0);
  EXPECT_EQ(file_bytes(d.file("shy/mine.txt")), "precious\n") << "a folder holding a file of the user's stays";
  // Review 31, F5: another output's sheets, that output still there, are not this one's to replace.
  ASSERT_EQ(extract(videos, "g1.h5", {"--sheets", d.file("shz")}), 0);
  const std::string g1_sheets = file_bytes(d.file("shz/haptex-files.json"));
  EXPECT_EQ(extract(woven, "g2.h5", {"--sheets", d.file("shz"), "--force"}), 2);
  EXPECT_EQ(file_bytes(d.file("shz/haptex-files.json")), g1_sheets) << "g1.h5's sheets";
  // Another run's sheets now at the name the earlier file recorded: not that file's, so they stay.
  fs::rename(d.file("shz"), d.file("shz_g1"));
  ASSERT_EQ(extract(woven, "g2.h5", {"--sheets", d.file("shz"), "--force"}), 0);
  ASSERT_EQ(extract(woven, "g1.h5", {"--force", "--no-sheets"}), 0);
  EXPECT_TRUE(fs::exists(d.file("shz/haptex-files.json"))) << "g2.h5's sheets";

  const auto train = [&](const std::string& model, std::vector<std::string> more) {
    std::vector<std::string> args = quick_train_args(p.dataset, p.split, d.file(model));
    args.insert(args.end(), more.begin(), more.end());
    return run_haptex(args).exit_code;
  };
  ASSERT_EQ(train("m.h5", {"--log", d.file("a.json")}), 0);
  ASSERT_EQ(train("m.h5", {"--force"}), 0);
  EXPECT_FALSE(fs::exists(d.file("a.json"))) << "the log of the model replaced";
  EXPECT_TRUE(fs::exists(d.file("m.training.json")));
  ASSERT_EQ(train("m.h5", {"--force", "--log", d.file("b.json")}), 0);
  const std::string m_log = file_bytes(d.file("b.json"));
  EXPECT_EQ(train("n.h5", {"--log", d.file("b.json"), "--force"}), 2) << "m.h5's log, m.h5 still there (review 31, F5)";
  EXPECT_EQ(file_bytes(d.file("b.json")), m_log);
  fs::rename(d.file("b.json"), d.file("b_m.json"));
  ASSERT_EQ(train("n.h5", {"--log", d.file("b.json"), "--force"}), 0);
  ASSERT_EQ(train("m.h5", {"--force"}), 0);
  EXPECT_TRUE(fs::exists(d.file("b.json"))) << "n.h5's log now, not the replaced model's";
}

// Review 28, F1: a copy (or a merge) of an output carries its record of its companions, and --force over
// the copy took the original's: its log, its sheets. A companion goes only when it names the output
// replaced (the log's model_file, the sheet folder's owner). F2: the earlier default log was kept when
// the model's path was spelled otherwise (./m.h5).
TEST(Force, ACopysRecordTakesNotTheOriginalsCompanions) {
  const SmallPipeline& p = small_pipeline();
  const TempDir d;
  const auto train = [&](const std::string& model, std::vector<std::string> more) {
    std::vector<std::string> args = quick_train_args(p.dataset, p.split, model);
    args.insert(args.end(), more.begin(), more.end());
    return run_haptex_in(d.path().string(), args).exit_code;
  };
  ASSERT_EQ(train("m.h5", {}), 0);
  fs::copy_file(d.file("m.h5"), d.file("m_copy.h5"));
  ASSERT_EQ(train("m_copy.h5", {"--force"}), 0);
  EXPECT_TRUE(fs::exists(d.file("m.training.json"))) << "m.h5's log";
  ASSERT_EQ(train("./m.h5", {"--force", "--log", "other.json"}), 0);
  EXPECT_FALSE(fs::exists(d.file("m.training.json"))) << "the replaced model's log, however its path is spelled";

  const std::string videos = (fs::path(p.recordings).parent_path() / "synth" / "gelsight").string();
  const auto extract = [&](const std::string& input, const std::string& output, std::vector<std::string> more) {
    std::vector<std::string> args{"capture", "extract", input, "-o", d.file(output), "-q"};
    args.insert(args.end(), more.begin(), more.end());
    return run_haptex(args).exit_code;
  };
  ASSERT_EQ(extract(videos, "g.h5", {}), 0);
  fs::copy_file(d.file("g.h5"), d.file("g_copy.h5"));
  ASSERT_EQ(run_haptex({"merge", "-o", d.file("all.h5"), d.file("g.h5"), "-q"}).exit_code, 0);
  ASSERT_EQ(extract(videos + "/Woven 1", "g_copy.h5", {"--force"}), 0);
  ASSERT_EQ(extract(videos + "/Woven 1", "all.h5", {"--force"}), 0);
  EXPECT_TRUE(fs::exists(d.file("g_sheets/haptex-files.json"))) << "g.h5's sheets";
}

// A dangling link at the output path is refused, with --force or without: it is not haptex's.
TEST(Force, ADanglingLinkAtTheOutputIsRefused) {
  const TempDir d;
  fs::create_symlink(d.file("nowhere.json"), d.file("s.json"));
  for (const bool force : {false, true}) {
    std::vector<std::string> args{"split", small_pipeline().dataset, "-o", d.file("s.json"), "--no-plots"};
    if (force) args.push_back("--force");
    expect_refusal(run_haptex(args), {d.file("s.json"), "symbolic link to nothing"});
    EXPECT_TRUE(fs::is_symlink(d.file("s.json")));
  }
  expect_refusal(run_haptex({"split", small_pipeline().dataset, "-o", d.file("x.plots")}), {"names the plot folder"});
}

// Review 10, C5: --force replaced a file of the same format that a newer haptex wrote (the README
// promises it never does); one an older haptex wrote it still replaces.
TEST(Force, AFileANewerHaptexWroteIsNotReplaced) {
  const SmallPipeline& p = small_pipeline();
  const TempDir d;
  const std::string windows = d.file("w.h5"), split = d.file("s.json");
  ASSERT_EQ(run_haptex({"windows", p.dataset, "--split", p.split, "-o", windows}).exit_code, 0);
  ASSERT_EQ(run_haptex({"split", p.dataset, "-o", split, "--no-plots"}).exit_code, 0);
  for (const std::string version : {"99.0.0", "v2.0.0", "1e9", "1.0.0 ", "0.0.1"}) {
    SCOPED_TRACE(version);
    Edit(windows).root().set_attr("haptex_version", version);
    nlohmann::json manifest = read_json(split);
    manifest["haptex_version"] = version;
    write_json(split, manifest);
    const CommandResult w = run_haptex({"windows", p.dataset, "--split", p.split, "-o", windows, "--force"});
    const CommandResult s = run_haptex({"split", p.dataset, "-o", split, "--no-plots", "--force"});
    if (version == "99.0.0") {
      expect_refusal(w, {windows, "was written by haptex 99.0.0, newer than this one"});
      expect_refusal(s, {split, "was written by haptex 99.0.0, newer than this one"});
    } else if (version != "0.0.1") {  // review 11, F4: versions no haptex writes were replaced
      expect_refusal(w, {windows, "which no haptex writes"});
      expect_refusal(s, {split, "which no haptex writes"});
    } else {
      EXPECT_EQ(w.exit_code, 0) << w.err;
      // An older version is replaceable, but this manifest was edited to say it (review 15, R10).
      expect_refusal(s, {split, "its bytes are not those haptex wrote"});
    }
  }
}

// Review 10, C1 and C2: a manifest name over 255 bytes was said to "name the plot folder itself"; a
// device, FIFO or socket at an output was called a folder.
TEST(Force, AnOutputThatCannotBeAFileSaysWhy) {
  const SmallPipeline& p = small_pipeline();
  const TempDir d;
  const std::string long_name = d.file(std::string(251, 'c') + ".json");
  expect_refusal(run_haptex({"split", p.dataset, "-o", long_name}), {"is longer than the file system allows"});
  ASSERT_EQ(::mkfifo(d.file("fifo.h5").c_str(), 0600), 0);
  fs::create_directory(d.file("folder.h5"));
  for (const bool force : {false, true}) {
    SCOPED_TRACE(force ? "--force" : "");
    std::vector<std::string> fifo{"windows", p.dataset, "--split", p.split, "-o", d.file("fifo.h5")}, folder = fifo;
    folder.back() = d.file("folder.h5");
    if (force) fifo.push_back("--force"), folder.push_back("--force");
    expect_refusal(run_haptex(fifo), {d.file("fifo.h5"), "is a device, FIFO or socket, not a file", "Name a regular file"});
    expect_refusal(run_haptex(folder), {d.file("folder.h5"), "is a folder"});
  }
  EXPECT_EQ(fs::status(d.file("fifo.h5")).type(), fs::file_type::fifo);
}

// Review 8: --force on an output that is a link to haptex's own file did the whole job, then refused
// saying that a link "took its place while this run wrote". It is refused before any work.
TEST(Force, ALinkAtTheOutputIsRefusedBeforeAnyWork) {
  const SmallPipeline& p = small_pipeline();
  const TempDir d;
  ASSERT_EQ(run_haptex({"split", p.dataset, "-o", d.file("s.json"), "--no-plots"}).exit_code, 0);
  const std::string merged = d.file("m.h5");
  ASSERT_EQ(run_haptex({"merge", p.recordings, "-o", merged}).exit_code, 0);
  fs::create_symlink(d.file("s.json"), d.file("s_link.json"));
  fs::create_symlink(merged, d.file("m_link.h5"));
  const std::vector<std::vector<std::string>> commands = {
      {"split", p.dataset, "-o", d.file("s_link.json"), "--no-plots", "--force"},
      {"merge", p.recordings, "-o", d.file("m_link.h5"), "--force"},
  };
  for (const auto& command : commands) {
    SCOPED_TRACE(command.front());
    expect_refusal(run_haptex(command), {"is a symbolic link, which --force does not replace"});
  }
  EXPECT_TRUE(fs::is_symlink(d.file("s_link.json")) && fs::is_symlink(d.file("m_link.h5")));
}

}  // namespace
}  // namespace haptex::test
