// A new user's first hour without dead ends (issue 35): the mistakes a user makes first get messages
// that name the real problem, and scripts that read --json get an answer on stdout even for an error.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>
#include <vector>

#include "tests/support/quick_models.hpp"
#include "tests/support/run_haptex.hpp"
#include "tests/support/small_pipeline.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {

bool says(const CommandResult& r, const std::string& text) { return r.err.find(text) != std::string::npos; }

TEST(FirstHour, AFileOfAnotherKindGivenForADatasetIsCalledWhatItIs) {
  const SmallPipeline& p = small_pipeline();
  const TempDir dir;
  for (const auto& [file, kind] : {std::pair{p.recordings, "a recordings file (haptex convert writes those)"},
                                   {p.gelsight, "a gelsight file (haptex capture extract writes those)"}}) {
    for (const std::vector<std::string>& args :
         {quick_train_args(file, p.split, dir.file("m.h5")), std::vector<std::string>{"windows", file, "--split", p.split, "-o", dir.file("w.h5")},
          std::vector<std::string>{"evaluate", file, "--split", p.split, "--model", quick_model(), "-o", dir.file("r")},
          std::vector<std::string>{"view", file, "--split", p.split, "-o", dir.file("v")}}) {
      SCOPED_TRACE(args[0] + " " + file);
      const CommandResult r = run_haptex(args);
      EXPECT_EQ(r.exit_code, 2);
      EXPECT_TRUE(says(r, kind)) << r.err;
      EXPECT_TRUE(says(r, "not a dataset file (dataset/")) << r.err;
      EXPECT_FALSE(says(r, "another dataset")) << r.err;
    }
  }
}

TEST(FirstHour, AWrongMaterialListsTheModelsIds) {
  const CommandResult r = run_haptex({"predict", quick_model(), "--material", "no_such", "--normal-force", "1", "--speed", "100"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(says(r, "no material 'no_such'")) << r.err;
  EXPECT_TRUE(says(r, small_material())) << "the ids are listed: " << r.err;
  const CommandResult info = run_haptex({"info", quick_model()});
  ASSERT_EQ(info.exit_code, 0) << info.err;
  EXPECT_NE(info.out.find(small_material()), std::string::npos) << info.out;
}

TEST(FirstHour, AMissingRequiredOptionNamesTheSubcommandAndItsHelp) {
  const CommandResult train = run_haptex({"train"});
  EXPECT_EQ(train.exit_code, 2);
  EXPECT_EQ(train.err.rfind("haptex train: ", 0), 0u) << train.err;
  EXPECT_TRUE(says(train, "Run 'haptex train --help'")) << train.err;
  const CommandResult unknown = run_haptex({"nosuch"});  // review 13, C3: said "A subcommand is required"
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_TRUE(says(unknown, "'nosuch' is no haptex command. Run 'haptex --help' for the list")) << unknown.err;
  const CommandResult extract = run_haptex({"capture", "extract"});
  EXPECT_EQ(extract.exit_code, 2);
  EXPECT_EQ(extract.err.rfind("haptex capture extract: ", 0), 0u) << extract.err;
}

TEST(FirstHour, WithJsonAnErrorIsAnObjectOnStdoutToo) {
  const SmallPipeline& p = small_pipeline();
  const TempDir dir;
  const CommandResult r = run_haptex({"--json", "windows", p.gelsight, "--split", p.split, "-o", dir.file("w.h5")});
  EXPECT_EQ(r.exit_code, 2);
  const nlohmann::json e = nlohmann::json::parse(r.out)["error"];
  EXPECT_EQ(e["command"], "windows");
  EXPECT_EQ(e["exit_code"], 2);
  EXPECT_EQ(e["file"], p.gelsight);
  EXPECT_EQ(e["where"], "/@haptex_format");
  EXPECT_NE(e["message"].get<std::string>().find("not a dataset file"), std::string::npos) << e.dump();
  EXPECT_TRUE(says(r, e["message"].get<std::string>())) << "the same message on stderr";
  // A usage error, and --json after the subcommand's own options.
  const CommandResult usage = run_haptex({"train", "--json"});
  EXPECT_EQ(usage.exit_code, 2);
  const nlohmann::json u = nlohmann::json::parse(usage.out)["error"];
  EXPECT_EQ(u["command"], "train");
  EXPECT_EQ(u["exit_code"], 2);
  EXPECT_TRUE(u["file"].is_null());
  // --version too (review 13, C4).
  const CommandResult version = run_haptex({"--json", "--version"});
  EXPECT_EQ(version.exit_code, 0);
  const std::string plain = run_haptex({"--version"}).out;  // "haptex 0.1.0\n"
  EXPECT_EQ(nlohmann::json::parse(version.out)["haptex_version"], plain.substr(7, plain.size() - 8));
  EXPECT_EQ(nlohmann::json::parse(version.out)["formats"]["hdf5_written"][2], "dataset/4");
  // --help too: stdout is one JSON document whenever --json is given (review 13).
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{{"--json", "capture", "extract", "--help"}, {"train", "--help", "--json"}, {"--json", "--help"}}) {
    const CommandResult help = run_haptex(args);
    EXPECT_EQ(help.exit_code, 0);
    ASSERT_TRUE(nlohmann::json::accept(help.out)) << help.out;
    const nlohmann::json doc = nlohmann::json::parse(help.out);
    EXPECT_NE(doc["help"].get<std::string>().find("Usage:"), std::string::npos) << help.out;
    EXPECT_EQ(doc["command"], args[0] == "--json" && args.size() == 4 ? "capture extract" : args[0] == "train" ? "train" : "");
  }
}

TEST(FirstHour, EveryCommandsHelpListsTheFlagsAllCommandsTake) {
  const CommandResult top = run_haptex({"--help"});
  ASSERT_EQ(top.exit_code, 0);
  std::size_t commands = 0;
  for (const char* name : {"convert", "capture", "synth", "align", "merge", "split", "qa", "info", "train", "windows", "predict",
                           "render", "play", "view", "evaluate"}) {
    if (top.out.find(std::string("\n  ") + name + " ") == std::string::npos) continue;
    ++commands;
    const CommandResult help = run_haptex({name, "--help"});
    EXPECT_EQ(help.exit_code, 0) << name;
    for (const char* flag : {"--json", "-q,--quiet", "-v,--verbose"}) EXPECT_NE(help.out.find(flag), std::string::npos) << name << " " << flag;
  }
  EXPECT_GE(commands, 15u) << top.out;
  for (const char* part : {"record", "extract", "devices"}) {
    const CommandResult help = run_haptex({"capture", part, "--help"});
    EXPECT_NE(help.out.find("--json"), std::string::npos) << "capture " << part;
  }
}

// Numbers in the docs that the code produces are checked against it (issue 35): docs/qa.md's example
// run on a recordings file says how many checks such a file gets.
TEST(FirstHour, TheQaPagesExampleCountsTheChecksOfARecordingsFile) {
  std::ifstream in(std::string(HAPTEX_SCHEMA_DIR) + "/../docs/qa.md");
  const std::string page(std::istreambuf_iterator<char>(in), {});
  std::smatch documented;
  ASSERT_TRUE(std::regex_search(page, documented, std::regex("\\$ haptex qa recordings.h5[^$]*?in ([0-9]+) checks\\)")));
  const CommandResult r = run_haptex({"qa", small_pipeline().recordings});
  ASSERT_EQ(r.exit_code, 0) << r.out;
  std::smatch ran;
  ASSERT_TRUE(std::regex_search(r.out, ran, std::regex("in ([0-9]+) checks\\)"))) << r.out;
  EXPECT_EQ(documented[1], ran[1]);
}

}  // namespace
}  // namespace haptex::test
