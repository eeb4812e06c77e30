// Issue 11 point 3: nothing non-finite is trained on, written or printed with exit code 0. A dataset
// window holding NaN stops train before any epoch; a model holding NaN, infinity or a zero scale is
// refused by every command that loads it, naming the file and the array; no floating-point option
// takes NaN or infinity.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <fstream>
#include <limits>
#include <regex>
#include <sstream>

#include "core/sha256.hpp"
#include "tests/hostile/hostile_support.hpp"
#include "tests/support/mutations.hpp"
#include "tests/support/quick_models.hpp"
#include "tests/support/small_pipeline.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {
namespace fs = std::filesystem;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// A copy of the dataset with one value of window 7 replaced, and the split re-pointed at it.
struct DamagedDataset {
  TempDir dir;
  std::string dataset, split;
  DamagedDataset(const std::string& array, std::size_t index, float value) {
    dataset = copy_into(dir, small_pipeline().dataset, "d.h5");
    {
      Edit edit(dataset);
      edit.change_floats(array, [&](std::vector<float>& v) { v.at(index) = value; });
    }
    nlohmann::json manifest = read_json(small_pipeline().split);
    manifest["dataset"]["sha256"] = sha256_file(dataset);
    split = dir.file("split.json");
    write_json(split, manifest);
  }
};

TEST(NonFinite, TrainRefusesAWindowWithNaNBeforeAnyEpoch) {
  for (const auto& [array, index] : {std::pair{"windows/target", std::size_t(7 * 100 + 3)}, std::pair{"windows/action", std::size_t(7 * 20 + 1)}}) {
    SCOPED_TRACE(array);
    const DamagedDataset d(array, index, kNaN);
    const CommandResult r = run_haptex(quick_train_args(d.dataset, d.split, d.dir.file("m.h5")));
    expect_refusal(r, {d.dataset, "/windows[7] (", "recording ", "start ", "nan"});
    EXPECT_EQ(r.err.find("epoch"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(d.dir.file("m.h5")));
    EXPECT_FALSE(fs::exists(d.dir.file("m.training.json")));
  }
}

// The command paths (e.g. "capture extract") under `path`, from the help's Subcommands section.
std::vector<std::vector<std::string>> commands_under(std::vector<std::string> path) {
  std::vector<std::string> args = path;
  args.push_back("--help");
  std::istringstream help(run_haptex(args).out);
  std::vector<std::vector<std::string>> found;
  bool listing = false;
  static const std::regex subcommand("^  ([a-z-]+) {2,}.*");
  std::smatch m;
  for (std::string line; std::getline(help, line);) {
    if (line.rfind("Subcommands:", 0) == 0) listing = true;
    else if (line.empty()) listing = false;  // the list ends; the flags every command takes follow
    else if (listing && std::regex_match(line, m, subcommand)) {
      std::vector<std::string> sub = path;
      sub.push_back(m[1]);
      const auto deeper = commands_under(sub);
      found.insert(found.end(), deeper.begin(), deeper.end());
    }
  }
  if (found.empty() && !path.empty()) found.push_back(path);
  return found;
}

// Calls `each` with every command path and each line of its --help.
void for_each_help_line(const std::function<void(const std::vector<std::string>& command, const std::string& line)>& each) {
  for (const auto& command : commands_under({})) {
    std::vector<std::string> help_args = command;
    help_args.push_back("--help");
    std::istringstream help(run_haptex(help_args).out);
    for (std::string line; std::getline(help, line);) each(command, line);
  }
}

// CLI11 reads "nan" and "inf" as numbers, and range checks let NaN through: every option whose help
// says FLOAT, in every command, refuses them before any work; 1e39 too, which a 32-bit float holds as
// inf. A POSITIVE one refuses 1e-320, which a 32-bit float holds as 0 (review 3: --trigger 1e-320
// found a "press" in every frame); every one refuses a subnormal 5e-40 (review 4: --normal-force 5e-40
// and record --seconds 1e-40 were taken).
void expect_float_option_refuses(const std::vector<std::string>& command, const std::string& option, const std::string& line) {
  // One of each kind, signs alternating: every run of haptex costs its start-up (about 0.3 s).
  std::vector<std::string> values = {"nan", "-inf", "1e39", "-5e-40"};
  if (line.find("POSITIVE") != std::string::npos) values.push_back("1e-320");
  for (const std::string& value : values) {
    std::vector<std::string> args = command;
    args.push_back(option + "=" + value);
    SCOPED_TRACE(args.front() + " " + args.back());
    const CommandResult r = run_haptex(args);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find(option + ": "), std::string::npos) << r.err;
    if (value == "nan") {
      EXPECT_NE(r.err.find("must be a finite number"), std::string::npos) << r.err;
    }
    if (value == "1e-320") {
      EXPECT_NE(r.err.find("at least 1.2e-38"), std::string::npos) << r.err;
    }
    EXPECT_FALSE(std::regex_search(r.err, std::regex("[0-9]{20}"))) << "no bound of 309 digits: " << r.err;
  }
}

// Review 4, #11: split --seed 2^63 did all its work, then failed on its own manifest's schema; train,
// render and evaluate took 2^64 and beyond. Every --seed takes 0 to 2^53, which JSON keeps exact.
void expect_seed_option_refuses(const std::vector<std::string>& command, const std::string& line) {
  static const std::regex seed_option("^ *--seed [A-Z0-9]*:SEED.*");
  EXPECT_TRUE(std::regex_match(line, seed_option)) << line;
  for (const std::string value : {"9223372036854775808", "9007199254740993", "-1"}) {
    std::vector<std::string> args = command;
    args.push_back("--seed=" + value);
    SCOPED_TRACE(args.front() + " " + args.back());
    expect_refusal(run_haptex(args), {"--seed", "0 to 9007199254740992"});
  }
}

// One walk over every command's help for both (each --help costs a start-up).
TEST(NonFinite, NoNumberOptionTakesWhatItCannotHold) {
  static const std::regex float_option("^ *(--[a-z-]+) FLOAT.*");
  int floats = 0, seeds = 0;
  for_each_help_line([&](const std::vector<std::string>& command, const std::string& line) {
    std::smatch m;
    if (std::regex_match(line, m, float_option)) {
      ++floats;
      expect_float_option_refuses(command, m[1].str(), line);
    }
    if (line.find("--seed") != std::string::npos) {
      ++seeds;
      expect_seed_option_refuses(command, line);
    }
  });
  EXPECT_GE(floats, 9) << "the help lists the floating-point options";
  EXPECT_GE(seeds, 6) << "split, train, render, evaluate, synth hatt and synth materials";
}

// The model's arrays a damaged or diverged training could leave, and what loading it must say.
struct ModelDamage {
  std::string array;
  float value;
  std::string says;
};

TEST(NonFinite, EveryCommandRefusesAModelWithNaNInfinityOrAZeroScale) {
  const std::vector<ModelDamage> damages = {
      {"nets/0/predictor/layers/0/weight", kNaN, "not a finite number"},
      {"nets/0/action_encoder/layers/0/bias", kInf, "not a finite number"},
      {"material_latents", kInf, "not a finite number"},
      {"classifier/layers/0/weight", kNaN, "not a finite number"},
      {"normalisation/action_scale", 0.0f, "must be positive"},
      {"normalisation/target_scale", -1.0f, "must be positive"},
      {"normalisation/action_mean", kNaN, "not a finite number"},
  };
  const SmallPipeline& p = small_pipeline();
  for (const ModelDamage& damage : damages) {
    SCOPED_TRACE(damage.array);
    const TempDir dir;
    const std::string model = copy_into(dir, quick_model(), "m.h5");
    {
      Edit edit(model);
      edit.change_floats(damage.array, [&](std::vector<float>& v) { v.at(0) = damage.value; });
    }
    std::ofstream trajectory(dir.file("t.csv"));
    trajectory << "force,speed\n";
    for (int i = 0; i < 2000; ++i) trajectory << "1,100\n";
    trajectory.close();
    const std::string material = read_json(p.split)["materials"][0]["id"];
    const std::vector<std::string> mentions = {model, "/" + damage.array, damage.says};
    expect_refusal(run_haptex({"predict", model, "--material", material, "--normal-force", "1", "--speed", "100"}), mentions);
    expect_refusal(run_haptex({"predict", model, "--material", material, "--normal-force", "1", "--speed", "100", "--json"}), mentions);
    expect_refusal(run_haptex({"render", model, "--material", material, "--trajectory", dir.file("t.csv"), "-o", dir.file("o.wav")}),
                   mentions);
    EXPECT_FALSE(fs::exists(dir.file("o.wav")));
    expect_refusal(run_haptex({"evaluate", p.dataset, "--split", p.split, "--model", model, "-o", dir.file("report")}), mentions);
    EXPECT_FALSE(fs::exists(dir.file("report")));
  }
}

// Review 2, #9: weights that are each finite but overflow 32-bit floats together (3e38 in a layer)
// gave "inf" spectra with exit 0 (predict) or an error naming no file (render, evaluate). Loading
// runs the model once per material at the corners of its force-speed range and refuses it.
// Review 3, #8: the refusal named the layer where the inf showed (/nets/0/predictor for a runaway
// action-encoder bias or target scale; the texture encoder for a subnormal descriptor scale), not the
// one that was changed. It names the first layer whose values run away, else the scale.
struct Overflow {
  std::string array;
  float value;
  std::vector<std::string> says;
};

TEST(NonFinite, AModelWhoseFiniteWeightsOverflowIsRefused) {
  const SmallPipeline& p = small_pipeline();
  const std::vector<Overflow> cases = {
      {"nets/0/predictor/layers/1/weight", 3e38f, {"/nets/0/predictor/layers/1", "non-finite"}},
      {"texture_encoder/layers/0/weight", 3e38f, {"/texture_encoder/layers/0", "non-finite"}},
      {"nets/0/action_encoder/layers/1/bias", 3e38f, {"/nets/0/action_encoder/layers/1", "non-finite"}},
      {"normalisation/target_scale", 3e38f, {"/normalisation/target_scale", "non-finite"}},
      {"normalisation/descriptor_scale", 1e-45f, {"/normalisation/descriptor_scale", "at least 1.2e-38"}},
      // Review 4, #6: finite spectra of 1e30 m/s^2 passed predict, and render wrote NaN (exit 1).
      {"normalisation/target_scale", 1e30f, {"/normalisation/target_scale", "absurd", "past 1e+06 m/s^2"}},
      {"nets/0/predictor/layers/0/weight", 1e30f, {"/nets/0/predictor/layers/0", "absurd"}},
      {"nets/0/predictor/layers/1/bias", 1e20f, {"/nets/0/predictor/layers/1", "absurd"}},
  };
  for (const Overflow& c : cases) {
    SCOPED_TRACE(c.array);
    const TempDir dir;
    const std::string model = copy_into(dir, quick_model(), "m.h5");
    Edit(model).change_floats(c.array, [&](std::vector<float>& v) { std::fill(v.begin(), v.end(), c.value); });
    std::ofstream trajectory(dir.file("t.csv"));
    trajectory << "force,speed\n";
    for (int i = 0; i < 20; ++i) trajectory << "1,100\n";
    trajectory.close();
    const std::string material = read_json(p.split)["materials"][0]["id"];
    std::vector<std::string> mentions = c.says;
    mentions.insert(mentions.end(), {model, "Train the model again"});
    expect_refusal(run_haptex({"predict", model, "--material", material, "--normal-force", "1", "--speed", "100"}), mentions);
    expect_refusal(run_haptex({"render", model, "--material", material, "--trajectory", dir.file("t.csv"), "-o", dir.file("o.wav")}),
                   mentions);
    EXPECT_FALSE(fs::exists(dir.file("o.wav")));
    expect_refusal(run_haptex({"evaluate", p.dataset, "--split", p.split, "--model", model, "-o", dir.file("report")}), mentions);
    EXPECT_FALSE(fs::exists(dir.file("report")));
  }
}

}  // namespace
}  // namespace haptex::test
