// Issue 11 point 1: a material name and output paths that spell commands for gnuplot or a shell go
// through convert, capture extract, align, split, train and evaluate; nothing they spell runs, and
// the charts still carry a readable title.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>

#include "core/process/run_program.hpp"
#include "tests/hostile/hostile_support.hpp"
#include "tests/support/quick_models.hpp"
#include "tests/support/sample_recording.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {
namespace fs = std::filesystem;

// gnuplot runs `touch x` inside double quotes; the single-quoted part breaks out of a '...' title
// into system(). No slash, so the name can also be a press folder's.
const std::string kEvilName = "Evil `touch x` 1' ; system 'touch y' ; y = '";
// What haptex shows of it in a chart title: quotes and back-quotes made typographic.
const std::string kReadableName = "Evil \u2018touch x\u2018 1\u2019 ; system \u2019touch y\u2019 ; y = \u2019";
const std::vector<std::string> kMarkers = {"x", "y", "z", "w"};

void run_ok(const std::vector<std::string>& args) {
  const CommandResult r = run_haptex(args);
  ASSERT_EQ(r.exit_code, 0) << args[0] << ": " << r.err;
}

std::string read(const fs::path& path) { return file_bytes(path.string()); }

// Renames material `name` to kEvilName in synth's recordings and press folders.
void rename_material(const fs::path& synth, const std::string& name, const std::string& id) {
  for (const auto& entry : fs::directory_iterator(synth / "recordings")) {
    if (entry.path().filename().string().rfind(id + "_", 0) != 0) continue;
    std::string xml = read_recording_text(entry.path().string());
    xml = std::regex_replace(xml, std::regex("<material>" + name + "</material>"), "<material>" + kEvilName + "</material>");
    write_recording_text(entry.path().string(), xml);
  }
  fs::rename(synth / "gelsight" / name, synth / "gelsight" / kEvilName);
}

TEST(HostileNames, RunNothingFromConvertToEvaluate) {
  const TempDir dir;
  const fs::path root = dir.path();
  const std::string synth = dir.file("synth");
  run_ok({"synth", "materials", "-n", "2", "--presses", "5", "--recordings", "1", "--seconds", "3", "-o", synth});
  rename_material(synth, "Sandpaper 1", "sandpaper_1");
  run_ok({"convert", "hatt", synth + "/recordings", "-o", dir.file("r.h5")});
  run_ok({"capture", "extract", synth + "/gelsight", "-o", dir.file("g.h5")});
  run_ok({"align", "--recordings", dir.file("r.h5"), "--gelsight", dir.file("g.h5"), "-o", dir.file("d.h5")});
  fs::create_directory(root / "q");
  const std::string split = dir.file("q/a'`touch z`'.json");
  run_ok({"split", dir.file("d.h5"), "-o", split});
  run_ok(quick_train_args(dir.file("d.h5"), split, dir.file("m.h5")));
  run_ok({"evaluate", dir.file("d.h5"), "--split", split, "--model", dir.file("m.h5"), "--repeats", "2", "-o",
          dir.file("rep'`touch w`'")});

  EXPECT_EQ(files_named(root.string(), kMarkers), std::vector<std::string>{});
  EXPECT_EQ(files_named(fs::current_path().string(), kMarkers), std::vector<std::string>{});

  // The split plot of the renamed material: the readable title, no back-quote left in the script.
  const std::string id = "evil_touch_x_1_system_touch_y_y";
  const std::string script = read(root / "q" / "a'`touch z`'.plots" / (id + ".gnuplot"));
  EXPECT_NE(script.find(kReadableName), std::string::npos) << script.substr(0, 600);
  EXPECT_EQ(script.find('`'), std::string::npos);
  const std::string bars = read(root / "rep'`touch w`'" / "experiment-unified-new-actions.gnuplot");
  EXPECT_NE(bars.find(kReadableName), std::string::npos);
  EXPECT_EQ(bars.find('`'), std::string::npos);
  if (!process::program_on_path("gnuplot")) GTEST_SKIP() << "gnuplot is not installed: the scripts were checked, not drawn";
  EXPECT_TRUE(fs::is_regular_file(root / "q" / "a'`touch z`'.plots" / (id + ".png")));
  EXPECT_TRUE(fs::is_regular_file(root / "rep'`touch w`'" / "experiment-unified-new-actions.png"));
}

}  // namespace
}  // namespace haptex::test
