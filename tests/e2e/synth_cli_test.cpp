// `haptex synth` as a user runs it: deterministic folders that the real pipeline reads unchanged.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <opencv2/videoio.hpp>

#include "core/h5/file.hpp"
#include "core/json/schema.hpp"
#include "core/naming.hpp"
#include "core/sha256.hpp"
#include "core/temporary_name.hpp"
#include "dataset/truth_file.hpp"
#include "tests/support/npy.hpp"
#include "tests/support/run_haptex.hpp"
#include "tests/support/sample_recording.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {
namespace fs = std::filesystem;

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

const std::vector<std::string> kSmall = {"--size", "160x120", "--presses", "2", "--recordings", "1", "--seconds", "0.5"};

// truth.h5 knows every recording by the SHA-256 convert stamps on it (the evaluation's noise floor
// finds a recording's truth that way): checks that link through the converted recordings file.
void expect_truth_of_each_recording(const dataset::Truth& truth, const std::string& recordings_file, std::size_t samples) {
  const h5::File converted = h5::File::open(recordings_file);
  for (const dataset::MaterialTruth& m : truth.materials)
    for (const dataset::TruthRecording& r : m.recordings) {
      SCOPED_TRACE(m.name + " recording " + std::to_string(r.index));
      const std::string k = "materials/" + material_id(m.name) + "/recordings/" + std::to_string(r.index);
      EXPECT_EQ(converted.root().open_group(k).attr_string("source_sha256"), r.source_sha256);
      EXPECT_EQ(r.speed_mm_s.size(), samples);
      EXPECT_EQ(r.force_n.size(), samples);
    }
}

CommandResult synth_materials(const std::string& out, std::vector<std::string> extra = {}) {
  std::vector<std::string> args = {"synth", "materials", "-n", "2", "-o", out};
  args.insert(args.end(), kSmall.begin(), kSmall.end());
  args.insert(args.end(), extra.begin(), extra.end());
  return run_haptex(args);
}

TEST(SynthCli, MaterialsAreByteIdenticalForASeed) {
  TempDir dir;
  setenv("SOURCE_DATE_EPOCH", "1700000000", 1);  // truth.h5 carries a creation time
  ASSERT_EQ(synth_materials(dir.file("a")).exit_code, 0);
  ASSERT_EQ(synth_materials(dir.file("b")).exit_code, 0);
  ASSERT_EQ(synth_materials(dir.file("c"), {"--seed", "1"}).exit_code, 0);
  unsetenv("SOURCE_DATE_EPOCH");
  std::size_t files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(dir.file("a"))) {
    if (!entry.is_regular_file()) continue;
    const fs::path relative = fs::relative(entry.path(), dir.file("a"));
    ASSERT_TRUE(fs::exists(fs::path(dir.file("b")) / relative)) << relative;
    EXPECT_EQ(slurp(entry.path()), slurp(fs::path(dir.file("b")) / relative)) << relative << " differs between runs";
    ++files;
  }
  EXPECT_EQ(files, 13u);  // 2 recordings, 4 press videos and their sidecars, truth, materials, manifest
  EXPECT_NE(slurp(fs::path(dir.file("a")) / "recordings/polished_1_0.xml.gz"),
            slurp(fs::path(dir.file("c")) / "recordings/polished_1_0.xml.gz"));
}

TEST(SynthCli, MaterialsReadBackThroughConvertOpenCvAndH5py) {
  TempDir dir;
  const std::string out = dir.file("out");
  const CommandResult made = synth_materials(out, {"--json"});
  ASSERT_EQ(made.exit_code, 0) << made.err;
  EXPECT_EQ(nlohmann::json::parse(made.out)["presses"], 4);

  const CommandResult converted = run_haptex({"convert", "hatt", out + "/recordings", "-o", dir.file("r.h5")});
  EXPECT_EQ(converted.exit_code, 0) << converted.err;
  EXPECT_NE(converted.out.find("2 recordings"), std::string::npos) << converted.out;

  for (const char* material : {"Polished 1", "Sandpaper 1"})
    for (int press = 0; press < 2; ++press) {
      const std::string base = out + "/gelsight/" + material + "/press_" + std::to_string(press);
      const nlohmann::json sidecar = json::read_file(base + ".json");
      cv::VideoCapture video(base + ".avi");
      ASSERT_TRUE(video.isOpened()) << base;
      int frames = 0;
      for (cv::Mat frame; video.read(frame); ++frames) ASSERT_EQ(frame.cols, 160);
      EXPECT_EQ(frames, sidecar["frames"].get<int>()) << base;
      EXPECT_GE(sidecar["contact_first"].get<int>(), 15);
    }

  EXPECT_NO_THROW(json::validate(json::read_file(out + "/materials.json"), "synth-materials.schema.json", "materials.json"));
  const dataset::Truth truth = dataset::read_truth_file(out + "/truth.h5");
  EXPECT_EQ(truth.accel_noise_m_s2, 0.02);
  ASSERT_EQ(truth.materials.size(), 2u);
  for (const dataset::MaterialTruth& m : truth.materials) {
    EXPECT_EQ(m.generator, "synth-material");
    EXPECT_EQ(nlohmann::json::parse(m.recipe_json)["name"], m.name);
    ASSERT_TRUE(m.grid.has_value()) << m.name;
    EXPECT_EQ(m.grid->spectra.size(), 10u * 8u * 100u);
    EXPECT_EQ(m.recordings.size(), 1u);
  }
  expect_truth_of_each_recording(truth, dir.file("r.h5"), 5000);
  if (!python_has("h5py")) GTEST_SKIP() << "python3-h5py is not installed";
  const CommandResult layout = run_python({std::string(HAPTEX_SCHEMA_DIR) + "/../tests/e2e/check_layout.py",
                                           std::string(HAPTEX_SCHEMA_DIR) + "/hdf5-layout.md", out + "/truth.h5", "Truth"});
  EXPECT_EQ(layout.exit_code, 0) << layout.out << layout.err;
}

TEST(SynthCli, RefusesANonEmptyFolderAndBadOptions) {
  TempDir dir;
  fs::create_directories(dir.file("full"));
  { std::ofstream(dir.file("full/keep.txt")) << "mine"; }
  const CommandResult refused = synth_materials(dir.file("full"));
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("not empty"), std::string::npos) << refused.err;
  EXPECT_EQ(slurp(dir.file("full/keep.txt")), "mine");
  EXPECT_EQ(run_haptex({"synth", "materials", "-o", dir.file("x"), "--size", "big"}).exit_code, 2);
  EXPECT_EQ(run_haptex({"synth", "materials", "-o", dir.file("x"), "--size", "160x120junk"}).exit_code, 2);
  EXPECT_EQ(run_haptex({"synth", "materials", "-o", dir.file("x"), "--size", "60000x45000"}).exit_code, 2);
  EXPECT_EQ(run_haptex({"synth", "materials", "-o", dir.file("x"), "-n", "0"}).exit_code, 2);
  const CommandResult no_models = run_haptex({"synth", "hatt", "--models", dir.file("full"), "-o", dir.file("y")});
  EXPECT_EQ(no_models.exit_code, 2);
  EXPECT_NE(no_models.err.find("no Models_<Material>.xml"), std::string::npos) << no_models.err;
}

TEST(SynthCli, ForceReplacesTheWholeFolder) {
  TempDir dir;
  ASSERT_EQ(synth_materials(dir.file("out")).exit_code, 0);
  const CommandResult again = run_haptex({"synth", "materials", "-n", "1", "-o", dir.file("out"), "--force", "--size", "160x120",
                                          "--presses", "1", "--recordings", "1", "--seconds", "0.5"});
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_FALSE(fs::exists(dir.file("out/recordings/sandpaper_1_0.xml.gz"))) << "a material of the earlier run survived";
  EXPECT_FALSE(fs::exists(dir.file("out/gelsight/Sandpaper 1")));
  EXPECT_TRUE(fs::exists(dir.file("out/recordings/polished_1_0.xml.gz")));
  EXPECT_TRUE(temporaries_of(dir.file("out")).empty());
}

TEST(SynthCli, AFailureHalfWayLeavesNoOutput) {
  const std::string data = shared_data_dir();
  if (data.empty()) GTEST_SKIP() << "../shared/data is absent: a published HaTT model is needed";
  TempDir dir;
  fs::create_directories(dir.file("models"));
  fs::create_directories(dir.file("images"));
  fs::copy_file(data + "/hatt/models/Models_Book.xml", dir.file("models/Models_Book.xml"));
  { std::ofstream(dir.file("images/Book_square.jpg")) << "not a jpeg"; }
  const CommandResult r = run_haptex({"synth", "hatt", "--models", dir.file("models"), "--images", dir.file("images"),
                                      "-o", dir.file("out"), "--seconds", "0.5"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("Book_square.jpg"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.file("out")));
  EXPECT_TRUE(temporaries_of(dir.file("out")).empty());
  const CommandResult no_images = run_haptex({"synth", "hatt", "--models", dir.file("models"), "--images", dir.file("nowhere"),
                                              "-o", dir.file("out2")});
  EXPECT_EQ(no_images.exit_code, 2);
  EXPECT_NE(no_images.err.find("not a folder"), std::string::npos) << no_images.err;
  // A photograph's name on a FIFO or a dangling link is refused by name, not skipped as "no photograph".
  fs::remove(dir.file("images/Book_square.jpg"));
  fs::create_symlink(dir.file("nowhere.jpg"), dir.file("images/Book_square.jpg"));
  const CommandResult dangling = run_haptex({"synth", "hatt", "--models", dir.file("models"), "--images", dir.file("images"),
                                             "-o", dir.file("out3"), "--seconds", "0.5"});
  EXPECT_EQ(dangling.exit_code, 2) << dangling.err;
  EXPECT_NE(dangling.err.find("Book_square.jpg"), std::string::npos) << dangling.err;
  EXPECT_FALSE(fs::exists(dir.file("out3")));
}

TEST(SynthCli, HattModelsAndPhotographsBecomeRecordingsAndPresses) {
  const std::string data = shared_data_dir();
  if (data.empty()) GTEST_SKIP() << "../shared/data is absent: the published HaTT models and images are needed";
  TempDir dir;  // two materials' models and photographs, copied to a scratch folder (never into the repo)
  fs::create_directories(dir.file("models"));
  fs::create_directories(dir.file("images"));
  for (const char* material : {"Book", "Cork"}) {
    fs::copy_file(data + "/hatt/models/Models_" + material + ".xml", dir.file("models/Models_" + std::string(material) + ".xml"));
    fs::copy_file(data + "/hatt/images/" + material + "_square.jpg", dir.file("images/" + std::string(material) + "_square.jpg"));
  }
  const std::string out = dir.file("out");
  const CommandResult made = run_haptex({"synth", "hatt", "--models", dir.file("models"), "--images", dir.file("images"),
                                         "-o", out, "--seconds", "1", "--json"});
  ASSERT_EQ(made.exit_code, 0) << made.err;
  const nlohmann::json summary = nlohmann::json::parse(made.out);
  EXPECT_EQ(summary["recordings"], 4);
  EXPECT_EQ(summary["presses"], 10);
  EXPECT_TRUE(fs::exists(out + "/recordings/book_1.xml.gz"));
  EXPECT_TRUE(fs::exists(out + "/gelsight/Cork/press_4.json"));
  EXPECT_TRUE(fs::exists(out + "/truth.h5"));
  const CommandResult converted = run_haptex({"convert", "hatt", out + "/recordings", "-o", dir.file("r.h5")});
  ASSERT_EQ(converted.exit_code, 0) << converted.err;

  // truth.h5: each model byte for byte, and the noise-free action of each recording.
  const dataset::Truth truth = dataset::read_truth_file(out + "/truth.h5");
  EXPECT_EQ(truth.accel_noise_m_s2, 0.02);
  ASSERT_EQ(truth.materials.size(), 2u);
  for (const dataset::MaterialTruth& m : truth.materials) {
    EXPECT_EQ(m.generator, "hatt-model");
    EXPECT_EQ(m.model_xml, slurp(dir.file("models/Models_" + m.name + ".xml"))) << m.name;
    EXPECT_FALSE(m.grid.has_value());
    ASSERT_EQ(m.recordings.size(), 2u);
    EXPECT_EQ(m.recordings[1].source_sha256, sha256_hex(read_recording_text(out + "/recordings/" + material_id(m.name) + "_1.xml.gz")));
  }
  expect_truth_of_each_recording(truth, dir.file("r.h5"), 10000);
  if (!python_has("h5py")) GTEST_SKIP() << "python3-h5py is not installed";
  const CommandResult layout = run_python({std::string(HAPTEX_SCHEMA_DIR) + "/../tests/e2e/check_layout.py",
                                           std::string(HAPTEX_SCHEMA_DIR) + "/hdf5-layout.md", out + "/truth.h5", "Truth"});
  EXPECT_EQ(layout.exit_code, 0) << layout.out << layout.err;
}

}  // namespace
}  // namespace haptex::test
