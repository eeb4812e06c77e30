// haptex train and haptex predict as a user runs them, on the small pipeline's dataset and split.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/h5/file.hpp"
#include "core/json/schema.hpp"
#include "core/temporary_name.hpp"
#include "tests/support/quick_models.hpp"
#include "tests/support/run_haptex.hpp"
#include "tests/support/small_pipeline.hpp"

namespace haptex::test {
namespace {
namespace fs = std::filesystem;

std::vector<std::string> train_args(const std::string& split, const std::string& model) {
  return quick_train_args(small_pipeline().dataset, split, model);
}

const std::string& trained_model() { return quick_model(); }

nlohmann::json edited_split(const std::function<void(nlohmann::json&)>& edit) {
  nlohmann::json doc = json::read_file(small_pipeline().split);
  edit(doc);
  return doc;
}

std::string write_json(const TempDir& dir, const nlohmann::json& doc) {
  const std::string path = dir.file("split.json");
  std::ofstream(path) << doc.dump(2);
  return path;
}

TEST(TrainCli, WritesTheModelAndAValidTrainingLog) {
  const TempDir dir;
  const CommandResult r = run_haptex(train_args(small_pipeline().split, dir.file("m.h5")));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("wrote " + dir.file("m.h5")), std::string::npos) << r.out;
  const nlohmann::json log = json::read_file(dir.file("m.training.json"));
  EXPECT_NO_THROW(json::validate(log, "training-log.schema.json", "log"));
  EXPECT_EQ(log["options"]["latent"], 8);
  EXPECT_EQ(log["options"]["target_smoothing"], 7);
  EXPECT_GE(log["epochs"].size(), 2u);
  // The source is the command line, every option kept (apps/provenance.hpp, in the order the command
  // declares them), without where the model went.
  const std::string source = log["source"];
  EXPECT_EQ(source.rfind("haptex train " + small_pipeline().dataset + " --split " + small_pipeline().split, 0), 0u) << source;
  const std::vector<std::string>& options = test::quick_train_options();
  for (std::size_t i = 0; i + 1 < options.size(); i += 2)
    EXPECT_NE(source.find(" " + options[i] + " " + options[i + 1]), std::string::npos) << options[i] << " missing from " << source;
  EXPECT_EQ(source.find(dir.file("m.h5")), std::string::npos) << source;
  EXPECT_EQ(h5::File::open(dir.file("m.h5")).root().attr_string("source"), source);
  // A second run refuses to overwrite without --force, and leaves the first model alone.
  const auto size = fs::file_size(dir.file("m.h5"));
  const CommandResult again = run_haptex(train_args(small_pipeline().split, dir.file("m.h5")));
  EXPECT_EQ(again.exit_code, 2);
  EXPECT_EQ(fs::file_size(dir.file("m.h5")), size);
}

// An even or out-of-range --target-smoothing is refused before any work, however it is written.
TEST(TrainCli, TargetSmoothingMustBeAnOddWholeNumber) {
  const TempDir dir;
  for (const char* width : {"4", "0", "101", "0x4", "3.0", "-3", "seven"}) {
    std::vector<std::string> args = train_args(small_pipeline().split, dir.file("m.h5"));
    args.insert(args.end(), {"--target-smoothing", width});
    const CommandResult r = run_haptex(args);
    EXPECT_EQ(r.exit_code, 2) << width;
    EXPECT_NE(r.err.find("--target-smoothing"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("epoch"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir.file("m.h5"))) << width;
  }
}

TEST(TrainCli, RefusesASplitMadeFromAnotherDataset) {
  const TempDir dir;
  const std::string split = write_json(dir, edited_split([](nlohmann::json& d) { d["dataset"]["sha256"] = std::string(64, '0'); }));
  const CommandResult r = run_haptex(train_args(split, dir.file("m.h5")));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(split), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("another dataset"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.file("m.h5")));
  EXPECT_TRUE(temporaries_of(dir.file("m.h5")).empty());
}

TEST(TrainCli, AMaterialWithoutValidationWindowsIsNamed) {
  const TempDir dir;
  std::string id;
  const std::string split = write_json(dir, edited_split([&](nlohmann::json& d) {
    auto& m = d["materials"][0];
    id = m["id"];
    for (const auto& s : m["sections"]["val"]) m["sections"]["train"].push_back(s);
    m["sections"]["val"] = nlohmann::json::array();
  }));
  const CommandResult r = run_haptex(train_args(split, dir.file("m.h5")));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(id + ": nothing in val"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.file("m.h5")));
}

std::string first_material() { return json::read_file(small_pipeline().split)["materials"][0]["id"]; }

TEST(PredictCli, PrintsOneHundredBinsAndFlagsOutOfRangeQueries) {
  const std::string material = first_material();
  const CommandResult r = run_haptex({"predict", trained_model(), "--material", material, "--normal-force", "1", "--speed", "100", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json out = nlohmann::json::parse(r.out);
  ASSERT_EQ(out["queries"].size(), 1u);
  ASSERT_EQ(out["queries"][0]["spectrum"].size(), 100u);
  for (double a : out["queries"][0]["spectrum"]) EXPECT_GE(a, 0.0);

  const CommandResult far = run_haptex({"predict", trained_model(), "--material", material, "--normal-force", "900", "--speed", "90000"});
  ASSERT_EQ(far.exit_code, 0) << far.err;
  EXPECT_NE(far.err.find("outside the training range"), std::string::npos) << far.err;
  EXPECT_EQ(std::count(far.out.begin(), far.out.end(), '\n'), 101);  // header + 100 bins
}

// Issue 33: --force means "replace the output" everywhere; predict's force is --normal-force, and the
// old spelling is refused naming the new one.
TEST(PredictCli, TheNormalForceIsNotCalledForce) {
  const CommandResult old = run_haptex({"predict", trained_model(), "--material", first_material(), "--force", "1.5", "--speed", "100"});
  EXPECT_EQ(old.exit_code, 2);
  EXPECT_NE(old.err.find("Write --normal-force 1.5"), std::string::npos) << old.err;
  const CommandResult alone = run_haptex({"predict", trained_model(), "--material", first_material(), "--speed", "100"});
  EXPECT_EQ(alone.exit_code, 2);
  EXPECT_NE(alone.err.find("give --normal-force and --speed"), std::string::npos) << alone.err;
}

TEST(PredictCli, FollowsATrajectoryAndRefusesABadOne) {
  const TempDir dir;
  {
    std::ofstream csv(dir.file("traj.csv"));
    csv << "time_s,force,speed\n";
    for (int i = 0; i < 1000; ++i) csv << i * 1e-4 << "," << 1.0 + i * 1e-3 << "," << 50 + i * 0.1 << "\n";
  }
  const std::string material = first_material();
  const CommandResult r = run_haptex({"predict", trained_model(), "--material", material, "--csv", dir.file("traj.csv")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1 + 10);  // header + samples 0, 100, ..., 900
  // From the first sample on: before it, the first sample stands in for the 45 ms of action.
  EXPECT_EQ(r.out.find("\n0,0.0000,1,50,"), r.out.find('\n')) << r.out.substr(0, 300);
  EXPECT_NE(r.out.find("\n900,0.0900,1.9,140,"), std::string::npos) << r.out;
  {
    std::ofstream csv(dir.file("bad.csv"));
    csv << "time_s,force,speed\n0,1,50\n0.0001,x,50\n";
  }
  const CommandResult bad = run_haptex({"predict", trained_model(), "--material", material, "--csv", dir.file("bad.csv")});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find(dir.file("bad.csv") + ": line 3"), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace haptex::test
