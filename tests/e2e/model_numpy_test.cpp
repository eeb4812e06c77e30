// The model file as a numpy user sees it: `haptex train` on the small pipeline, `haptex predict --json`
// on a press image from the dataset and on a training material, and tests/e2e/model_forward.py
// (h5py and numpy only, following schemas/hdf5-layout.md's "Model file" section) recomputes the
// latent and the spectra from the file and compares.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/h5/file.hpp"
#include "predict/model_file.hpp"
#include "dataset/press_images.hpp"
#include "tests/support/run_haptex.hpp"
#include "tests/support/small_pipeline.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {

const std::string kScript = std::string(HAPTEX_SCHEMA_DIR) + "/../tests/e2e/model_forward.py";

bool have_numpy() { return python_has("h5py, numpy"); }

// A dataset image (`reference` or `peak` of a press) as a PNG a user would pass to haptex predict.
void write_press_png(const std::string& dataset, const std::string& object, const std::string& png) {
  const auto slash = object.rfind('/');
  const h5::Group press = h5::File::open(dataset).root().open_group(object.substr(0, slash));
  ASSERT_TRUE(cv::imwrite(png, dataset::read_press_image(press, object.substr(slash + 1)))) << png;
}

CommandResult check(const std::string& model, const std::string& json_file) {
  return run_python({kScript, model, json_file});
}

std::string write_json(const TempDir& dir, const std::string& name, const nlohmann::json& doc) {
  const std::string path = dir.file(name);
  std::ofstream(path) << doc.dump(2);
  return path;
}

// Files shared by the tests of one process (ctest runs each test in its own): each model is trained
// when a test first needs it.
struct Trained {
  TempDir dir;
  std::string peak = dir.file("peak.png"), reference = dir.file("reference.png");
  std::vector<std::string> materials;
  float force = 0, speed = 0;  // the middle of the unified model's training range
};

Trained& trained() {
  static Trained t;
  if (t.materials.empty()) {
    const SmallPipeline& files = small_pipeline();
    t.materials = h5::File::open(files.dataset).root().open_group("materials").children();
    const std::string press = "materials/" + t.materials.back() + "/presses/4/";
    write_press_png(files.dataset, press + "peak", t.peak);
    write_press_png(files.dataset, press + "reference", t.reference);
  }
  return t;
}

// haptex train with small sizes; empty when it failed (the failure is reported).
std::string train(bool per_material) {
  const SmallPipeline& files = small_pipeline();
  Trained& t = trained();
  const std::string model = t.dir.file(per_material ? "per_material.h5" : "unified.h5");
  std::vector<std::string> args = {"train", files.dataset, "--split", files.split, "-o", model, "-q",
                                   "--latent", "8", "--texture-hidden", "16", "--action-hidden", "8",
                                   "--hidden", "16", "--epochs", "5", "--seed", "3"};
  if (per_material) args.push_back("--per-material");
  const CommandResult r = run_haptex(args);
  EXPECT_EQ(r.exit_code, 0) << r.err << r.out;
  if (r.exit_code != 0) return "";
  const predict::Normalisation n = predict::read_model(model).normalisation;
  t.force = 0.5f * (n.force_min + n.force_max), t.speed = 0.5f * (n.speed_min + n.speed_max);
  return model;
}

const std::string& unified_model() {
  static const std::string model = train(false);
  return model;
}

const std::string& per_material_model() {
  static const std::string model = train(true);
  return model;
}

class ModelFile : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!have_numpy()) GTEST_SKIP() << "/usr/bin/python3 lacks h5py or numpy (make deps installs python3-h5py)";
  }

  // haptex predict MODEL ARGS --json, its output kept in a file for the script.
  nlohmann::json predict_json(const std::string& model, std::vector<std::string> args, const std::string& name) {
    args.insert(args.begin(), {"predict", model});
    args.push_back("--json");
    const CommandResult r = run_haptex(args);
    EXPECT_EQ(r.exit_code, 0) << r.err << r.out;
    std::ofstream(dir_.file(name)) << r.out;
    return r.exit_code == 0 ? nlohmann::json::parse(r.out) : nlohmann::json();
  }

  static std::vector<std::string> in_range() {
    return {"--normal-force", std::to_string(trained().force), "--speed", std::to_string(trained().speed)};
  }

  static void expect_agrees(const std::string& model, const std::string& json_file) {
    const CommandResult r = check(model, json_file);
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("model forward ok"), std::string::npos) << r.out << r.err;
  }

  TempDir dir_;
};

TEST_F(ModelFile, NumpyRecomputesTheLatentAndSpectrumOfAnImage) {
  const std::string& model = unified_model();
  ASSERT_FALSE(model.empty());
  std::vector<std::string> args = {"--image", trained().peak, "--reference", trained().reference};
  std::vector<std::string> query = in_range();
  query.insert(query.begin(), args.begin(), args.end());
  const nlohmann::json out = predict_json(model, query, "image.json");
  ASSERT_TRUE(out.contains("descriptor") && out.contains("latent")) << out.dump();
  EXPECT_EQ(out["latent"].size(), 8u);
  EXPECT_FALSE(out["queries"][0]["out_of_range"].get<bool>());
  expect_agrees(model, dir_.file("image.json"));

  // Far outside the training range: the saturation step of the forward pass.
  args.insert(args.end(), {"--normal-force", "1000", "--speed", "100000"});
  const nlohmann::json far = predict_json(model, args, "far.json");
  EXPECT_TRUE(far["queries"][0]["out_of_range"].get<bool>());
  expect_agrees(model, dir_.file("far.json"));
}

TEST_F(ModelFile, NumpyRecomputesATrainingMaterialsSpectrum) {
  const std::string& model = unified_model();
  ASSERT_FALSE(model.empty());
  std::vector<std::string> args = in_range();
  args.insert(args.end(), {"--material", trained().materials.front()});
  const nlohmann::json out = predict_json(model, args, "material.json");
  ASSERT_TRUE(out.contains("latent")) << out.dump();
  EXPECT_FALSE(out.contains("descriptor"));
  expect_agrees(model, dir_.file("material.json"));
}

TEST_F(ModelFile, NumpyRunsEachMaterialsNetworkOfAPerMaterialModel) {
  const std::string& model = per_material_model();
  ASSERT_FALSE(model.empty());
  const std::vector<std::string>& materials = trained().materials;
  ASSERT_GE(materials.size(), 2u);
  for (const std::string& material : materials) {
    std::vector<std::string> args = in_range();
    args.insert(args.end(), {"--material", material});
    const nlohmann::json out = predict_json(model, args, material + ".json");
    EXPECT_EQ(out["variant"], "per-material");
    EXPECT_FALSE(out.contains("latent"));
    expect_agrees(model, dir_.file(material + ".json"));
  }
  // Another material's network gives another spectrum: the script must run network k for material k.
  nlohmann::json swapped = nlohmann::json::parse(std::ifstream(dir_.file(materials.front() + ".json")));
  swapped["material"] = materials.back();
  const CommandResult r = check(model, write_json(dir_, "swapped.json", swapped));
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
}

TEST_F(ModelFile, TheCheckFailsOnAPerturbedResult) {
  const std::string& model = unified_model();
  ASSERT_FALSE(model.empty());
  std::vector<std::string> args = {"--image", trained().peak, "--reference", trained().reference};
  const std::vector<std::string> query = in_range();
  args.insert(args.end(), query.begin(), query.end());
  const nlohmann::json out = predict_json(model, args, "image.json");
  ASSERT_TRUE(out.contains("descriptor")) << out.dump();
  expect_agrees(model, dir_.file("image.json"));

  // The largest spectrum bin 0.1% off (the check compares with the spectrum's largest value).
  nlohmann::json spectrum = out;
  const std::vector<double> bins = spectrum["queries"][0]["spectrum"];
  auto& bin = spectrum["queries"][0]["spectrum"][std::size_t(std::max_element(bins.begin(), bins.end()) - bins.begin())];
  bin = bin.get<double>() * 1.001;
  CommandResult r = check(model, write_json(dir_, "spectrum.json", spectrum));
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("mismatch: query 0: spectrum"), std::string::npos) << r.out << r.err;

  // A descriptor value changed: the recomputed encoder output no longer matches the printed one.
  nlohmann::json descriptor = out;
  descriptor["descriptor"][3] = descriptor["descriptor"][3].get<double>() + 5.0;
  r = check(model, write_json(dir_, "descriptor.json", descriptor));
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("mismatch: image_latent"), std::string::npos) << r.out << r.err;

  // The recognised latent changed: numpy's recognition disagrees.
  nlohmann::json recognised = out;
  recognised["latent"][0] = recognised["latent"][0].get<double>() + 1.0;
  r = check(model, write_json(dir_, "recognised.json", recognised));
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("mismatch: latent"), std::string::npos) << r.out << r.err;

  // A wrong saturation flag.
  nlohmann::json flag = out;
  flag["queries"][0]["out_of_range"] = true;
  r = check(model, write_json(dir_, "flag.json", flag));
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("mismatch: query 0: out_of_range"), std::string::npos) << r.out << r.err;
}

}  // namespace
}  // namespace haptex::test
