// Issue 11 point 3: nothing non-finite is trained on, written or printed with exit code 0. A dataset
// window holding NaN stops train before any epoch; a model holding NaN, infinity or a zero scale is
// refused by every command that loads it, naming the file and the array.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

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
    expect_refusal(run_haptex({"predict", model, "--material", material, "--force", "1", "--speed", "100"}), mentions);
    expect_refusal(run_haptex({"predict", model, "--material", material, "--force", "1", "--speed", "100", "--json"}), mentions);
    expect_refusal(run_haptex({"render", model, "--material", material, "--trajectory", dir.file("t.csv"), "-o", dir.file("o.wav")}),
                   mentions);
    EXPECT_FALSE(fs::exists(dir.file("o.wav")));
    expect_refusal(run_haptex({"evaluate", p.dataset, "--split", p.split, "--model", model, "-o", dir.file("report")}), mentions);
    EXPECT_FALSE(fs::exists(dir.file("report")));
  }
}

}  // namespace
}  // namespace haptex::test
