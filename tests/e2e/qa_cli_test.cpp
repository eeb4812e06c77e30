// `haptex qa` as a user runs it: the table and the JSON report (checked against
// schemas/qa-report.schema.json), exit codes 0 / 1 / 2, and bad input named with its fix.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "core/h5/file.hpp"
#include "core/json/schema.hpp"
#include "tests/support/pipeline_fixture.hpp"
#include "tests/support/run_haptex.hpp"
#include "tests/support/sample_recording.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {

class QaCli : public ::testing::Test {
 protected:
  // A dataset from align (sample recordings of 3 s, small synthetic presses) and its split (their smooth
  // sine-like strokes give no force-speed coverage to speak of; tests/qa covers coverage).
  static void SetUpTestSuite() {
    files_ = new PipelineFiles;
    PipelineSpec spec;
    spec.seconds = 3;
    make_pipeline_dataset(*files_, spec);
    split_ = files_->dir.file("split.json");
    const CommandResult r = run_haptex({"split", files_->dataset, "-o", split_, "--sections", "10", "--min-coverage", "0", "--no-plots"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  static void TearDownTestSuite() { delete files_; }

  static nlohmann::json report(const CommandResult& r) {
    const nlohmann::json doc = nlohmann::json::parse(r.out);
    EXPECT_NO_THROW(json::validate(doc, "qa-report.schema.json", "haptex qa --json"));
    return doc;
  }
  static std::string status_of(const nlohmann::json& doc, const std::string& id) {
    for (const auto& c : doc["checks"])
      if (c["id"] == id) return c["status"];
    return "absent";
  }

  static PipelineFiles* files_;
  static std::string split_;
  TempDir dir_;
};

PipelineFiles* QaCli::files_ = nullptr;
std::string QaCli::split_;

// A split that fails its own checks names the dataset, not the manifest it never wrote, and sends the
// user to no qa run on that missing file (review 13, C2).
TEST_F(QaCli, AFailedSplitNamesTheDatasetNotTheManifestItDidNotWrite) {
  const std::string wide = dir_.file("wide.h5"), manifest = dir_.file("never.json");
  ASSERT_EQ(run_haptex({"align", "--recordings", files_->recordings, "--gelsight", files_->gelsight, "--stride", "99999", "-o", wide, "-q"}).exit_code, 0);
  const CommandResult r = run_haptex({"split", wide, "-o", manifest, "--sections", "10", "--min-coverage", "0", "--no-plots"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.err.rfind("haptex split: error: " + wide + ": the split made from it fails split.", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("Nothing was written"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("never.json"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(manifest));
}

TEST_F(QaCli, RecordingsFileTableEndsWithTheVerdict) {
  const CommandResult r = run_haptex({"qa", files_->recordings});
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("haptex qa " + files_->recordings + " (recordings)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("ID"), std::string::npos);
  EXPECT_NE(r.out.find("SEVERITY"), std::string::npos);
  EXPECT_NE(r.out.find("signal.accel_spectrum"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("verdict: clean (0 errors, 0 warnings in 18 checks)"), std::string::npos) << r.out;
}

TEST_F(QaCli, DatasetWithSplitJsonFollowsTheSchema) {
  const CommandResult r = run_haptex({"qa", files_->dataset, "--split", split_, "--json"});
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  const nlohmann::json doc = report(r);
  EXPECT_EQ(doc["kind"], "dataset");
  EXPECT_EQ(doc["split"], split_);
  EXPECT_EQ(doc["errors"], 0) << r.out;
  for (const char* id : {"layout.required", "signal.nan", "gelsight.press_count", "dataset.cache", "split.coverage", "split.hashes"})
    EXPECT_EQ(status_of(doc, id), "pass") << id << "\n" << r.out;
}

TEST_F(QaCli, SplitManifestAlone) {
  const CommandResult r = run_haptex({"qa", split_, "--json"});
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  const nlohmann::json doc = report(r);
  EXPECT_EQ(doc["kind"], "split");
  EXPECT_EQ(doc["checks"].size(), 9u);
  EXPECT_EQ(status_of(doc, "split.hashes"), "pass");
}

TEST_F(QaCli, AnErrorExitsOneAndShowsTheFix) {
  const std::string copy = dir_.file("recordings.h5");
  std::filesystem::copy_file(files_->recordings, copy);
  h5::File::open(copy, true).root().open_group("materials/book/recordings/0").open_dataset("accel").set_attr("units", "g");
  const CommandResult r = run_haptex({"qa", copy, "-v"});
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("layout.units"), std::string::npos);
  EXPECT_NE(r.out.find("units 'g', expected 'm/s^2'"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("fix: Convert the source again"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("at /materials/book/recordings/0/accel"), std::string::npos) << r.out;  // -v lists places
  EXPECT_NE(r.out.find("verdict: errors (1 error, 0 warnings"), std::string::npos) << r.out;

  const CommandResult quiet = run_haptex({"qa", copy, "-q"});  // only what failed, and the verdict
  EXPECT_EQ(quiet.exit_code, 1);
  EXPECT_NE(quiet.out.find("layout.units"), std::string::npos) << quiet.out;
  EXPECT_EQ(quiet.out.find("signal.nan"), std::string::npos) << quiet.out;
  EXPECT_NE(quiet.out.find("verdict: errors"), std::string::npos) << quiet.out;

  const nlohmann::json doc = report(run_haptex({"qa", copy, "--json"}));
  EXPECT_EQ(doc["verdict"], "errors");
  EXPECT_EQ(status_of(doc, "layout.units"), "fail");
}

TEST_F(QaCli, WarningsAloneExitZero) {
  // A 2 s recording: too short for 25 sections to hold a window each (signal.short, a warning).
  SampleRecordingSpec spec;
  spec.seconds = 2;
  write_text_file(dir_.file("short.xml"), sample_recording_xml(spec));
  ASSERT_EQ(run_haptex({"convert", "hatt", dir_.file("short.xml"), "-o", dir_.file("short.h5")}).exit_code, 0);
  const CommandResult r = run_haptex({"qa", dir_.file("short.h5")});
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("verdict: warnings (0 errors, 1 warning"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("fix: Record longer strokes"), std::string::npos) << r.out;
}

TEST_F(QaCli, BadInputExitsTwoNamingFileAndFix) {
  write_text_file(dir_.file("notes.txt"), "not a haptex file\n");
  write_text_file(dir_.file("broken.json"), "{\"format\": ");
  struct Case {
    std::vector<std::string> args;
    std::vector<std::string> message;
  };
  const std::vector<Case> cases = {
      {{"qa", dir_.file("missing.h5")}, {dir_.file("missing.h5"), "no such file"}},
      {{"qa", dir_.file("notes.txt")}, {dir_.file("notes.txt"), "neither an HDF5 file nor a JSON split manifest"}},
      {{"qa", dir_.file("broken.json")}, {dir_.file("broken.json"), "not valid JSON"}},
      {{"qa", files_->gelsight, "--split", split_}, {files_->gelsight, "--split goes with a dataset file", "haptex qa DATASET.h5"}},
  };
  for (const auto& c : cases) {
    const CommandResult r = run_haptex(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args[1] << ": " << r.out << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    for (const auto& part : c.message) EXPECT_NE(r.err.find(part), std::string::npos) << part << " not in: " << r.err;
  }
  // An HDF5 file of a format qa does not check.
  {
    h5::File f = h5::File::create(dir_.file("truth.h5"));
    h5::stamp_root(f.root(), "truth/2", "test");
  }
  const CommandResult r = run_haptex({"qa", dir_.file("truth.h5")});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("is 'truth/2': qa checks recordings/1, gelsight/2 or dataset/4 files"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace haptex::test
