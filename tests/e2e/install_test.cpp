// haptex as a library others build on (issue 35, docs/library.md): `cmake --install` puts the binary,
// the modules' headers and static libraries, a CMake package and a pkg-config file under a prefix; a
// project of its own (examples/cpp_consumer) then builds against that tree both ways, reads a dataset
// and predicts, and its spectrum is the one haptex's own predictor gives.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "dataset/format.hpp"
#include "dataset/layout.hpp"
#include "dataset/press_images.hpp"
#include "dataset/window_table.hpp"
#include "predict/model_file.hpp"
#include "predict/predictor.hpp"
#include "tests/support/mutations.hpp"
#include "tests/support/quick_models.hpp"
#include "tests/support/run_haptex.hpp"
#include "tests/support/small_pipeline.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {
namespace fs = std::filesystem;

const std::string kConsumer = std::string(HAPTEX_SCHEMA_DIR) + "/../examples/cpp_consumer";

// One install of this build, made once.
const std::string& installed() {
  static const TempDir dir;
  static const std::string prefix = [] {
    const CommandResult r = run_program({"cmake", "--install", fs::path(HAPTEX_BINARY).parent_path().string(), "--prefix", dir.file("prefix")});
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    return dir.file("prefix");
  }();
  return prefix;
}

// What haptex's own predictor gives for the small pipeline's first window, as the consumer prints it.
std::string expected_output() {
  const dataset::WindowTable windows = dataset::read_window_table(dataset::open_checked(small_pipeline().dataset, dataset::Kind::dataset));
  const predict::Model model = predict::read_model(quick_model(false));
  predict::Predictor predictor(model);
  const std::string& material = windows.materials[std::size_t(windows.material[0])];
  std::vector<float> spectrum(dataset::kTargetBins);
  predictor.predict(predictor.material_code(model.material_index(material)), windows.action_of(0), spectrum);
  const h5::File file = dataset::open_checked(small_pipeline().dataset, dataset::Kind::dataset);
  const h5::Group press = file.root().open_group(dataset::layout::kMaterials).open_group(material).open_group(dataset::layout::kPresses).open_group("0");
  const std::size_t png = dataset::encode_png(dataset::read_press_image(press, dataset::layout::kPeak)).size();
  std::string out = "windows " + std::to_string(windows.size()) + "\nmaterial " + material + "\npeak png " + std::to_string(png) + " bytes\n";
  char value[32];
  for (const float a : spectrum) out += (std::snprintf(value, sizeof value, "%.9g\n", double(a)), value);
  return out;
}

std::vector<std::string> words(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

TEST(Install, PutsTheBinaryHeadersLibrariesAndBothPackageFilesUnderThePrefix) {
  const std::string prefix = installed();
  EXPECT_EQ(run_program({prefix + "/bin/haptex", "--version"}).exit_code, 0);
  EXPECT_TRUE(fs::is_regular_file(prefix + "/lib/haptex/libhaptex_opencv_codecs.so"));
  EXPECT_TRUE(fs::is_regular_file(prefix + "/lib/haptex/haptex-h5-probe"));
  for (const char* file : {"include/haptex/predict/predictor.hpp", "include/haptex/core/version.hpp", "include/haptex/evaluate/report/report_html.hpp",
                           "lib/libhaptex_core.a", "lib/libhaptex_predict.a", "lib/cmake/haptex/haptexConfig.cmake",
                           "lib/cmake/haptex/haptexConfigVersion.cmake", "lib/pkgconfig/haptex.pc"})
    EXPECT_TRUE(fs::is_regular_file(prefix + "/" + file)) << file;
}

// The installed binary loads its codecs plugin from lib/haptex (media/codecs.hpp) to write and read
// videos; without the plugin, a command that needs it says what is missing and how to get it back.
TEST(Install, TheInstalledBinaryFindsItsCodecsPluginAndSaysSoWhenItIsGone) {
  const TempDir dir;
  const std::string prefix = dir.file("copy");
  fs::copy(installed(), prefix, fs::copy_options::recursive);
  const std::vector<std::string> synth = {prefix + "/bin/haptex", "synth", "materials", "-n", "1", "--presses", "1", "--recordings", "1",
                                          "--seconds", "0.5", "--size", "64x48", "-q", "-o"};
  std::vector<std::string> args = synth;
  args.push_back(dir.file("s"));
  const CommandResult made = run_program(args);
  ASSERT_EQ(made.exit_code, 0) << made.err;
  const CommandResult extracted = run_program({prefix + "/bin/haptex", "capture", "extract", dir.file("s/gelsight"), "-o", dir.file("g.h5"), "-q"});
  EXPECT_EQ(extracted.exit_code, 0) << extracted.err;
  fs::remove(prefix + "/lib/haptex/libhaptex_opencv_codecs.so");
  args = synth;
  args.push_back(dir.file("t"));
  const CommandResult without = run_program(args);
  EXPECT_EQ(without.exit_code, 1);
  EXPECT_NE(without.err.find("cannot load OpenCV's image and video codecs"), std::string::npos) << without.err;
  EXPECT_NE(without.err.find("libhaptex_opencv_codecs.so"), std::string::npos) << without.err;
  EXPECT_NE(without.err.find("Reinstall haptex"), std::string::npos) << without.err;
  EXPECT_EQ(run_program({prefix + "/bin/haptex", "info", dir.file("g.h5")}).exit_code, 0) << "commands without images run as before";
  // lib/haptex/haptex-h5-probe reads a file's structure first (core/h5/structure_probe.hpp): a damaged
  // attribute header that crashes HDF5 is refused, not a crash.
  copy_with_damaged_attribute(dir.file("g.h5"), "fps", dir.file("damaged.h5"));
  const CommandResult damaged = run_program({prefix + "/bin/haptex", "info", dir.file("damaged.h5")});
  EXPECT_EQ(damaged.exit_code, 2) << damaged.err;
  EXPECT_NE(damaged.err.find("in haptex-h5-probe"), std::string::npos) << damaged.err;
}

TEST(Install, AProjectOfItsOwnBuildsWithFindPackageAndPredictsAsHaptexDoes) {
  const TempDir build;
  const CommandResult configure = run_program({"cmake", "-S", kConsumer, "-B", build.path(), "-DCMAKE_PREFIX_PATH=" + installed(), "-DCMAKE_BUILD_TYPE=Release"});
  ASSERT_EQ(configure.exit_code, 0) << configure.out << configure.err;
  const CommandResult make = run_program({"cmake", "--build", build.path()});
  ASSERT_EQ(make.exit_code, 0) << make.out << make.err;
  const CommandResult run = run_program({build.file("consumer"), small_pipeline().dataset, quick_model(false)});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, expected_output());
  const CommandResult wrong = run_program({build.file("consumer"), quick_model(false), quick_model(false)});
  EXPECT_EQ(wrong.exit_code, 2) << "the library's errors reach the program as haptex::Error";
  EXPECT_NE(wrong.err.find(quick_model(false)), std::string::npos) << wrong.err;
}

TEST(Install, AProjectOfItsOwnBuildsWithPkgConfig) {
  ::setenv("PKG_CONFIG_PATH", (installed() + "/lib/pkgconfig").c_str(), 1);
  const CommandResult flags = run_program({"pkg-config", "--cflags", "--libs", "haptex"});
  ::unsetenv("PKG_CONFIG_PATH");
  ASSERT_EQ(flags.exit_code, 0) << flags.err;
  const TempDir build;
  std::vector<std::string> compile = {"g++", "-O1", "-w", kConsumer + "/main.cpp", "-o", build.file("consumer")};
  for (const std::string& flag : words(flags.out)) compile.insert(compile.end() - 2, flag);
  const CommandResult make = run_program(compile);
  ASSERT_EQ(make.exit_code, 0) << make.err;
  const CommandResult run = run_program({build.file("consumer"), small_pipeline().dataset, quick_model(false)});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, expected_output());
}

// The version has one home, CMakeLists.txt's project(); CITATION.cff repeats it for citation tools,
// so it is checked here.
TEST(Install, CitationNamesTheVersionHaptexReports) {
  std::ifstream in(std::string(HAPTEX_SCHEMA_DIR) + "/../CITATION.cff");
  std::string line, cited;
  while (std::getline(in, line))
    if (line.rfind("version: ", 0) == 0) cited = line.substr(9);
  const CommandResult r = run_haptex({"--version"});
  ASSERT_EQ(r.exit_code, 0);
  EXPECT_EQ("haptex " + (cited.size() > 1 ? cited.substr(1, cited.size() - 2) : cited) + "\n", r.out) << "CITATION.cff's version: " << cited;
}

}  // namespace
}  // namespace haptex::test
