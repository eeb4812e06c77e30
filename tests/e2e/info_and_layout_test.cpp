// `haptex info`, and the recordings file as a Python user sees it (h5py) against schemas/hdf5-layout.md.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/json/schema.hpp"
#include "tests/support/run_haptex.hpp"
#include "tests/support/sample_recording.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {

class ConvertedFile : public ::testing::Test {
 protected:
  void SetUp() override {
    SampleRecordingSpec spec;
    spec.seconds = 0.5;
    write_text_file(dir_.file("canvas_1.xml"), sample_recording_xml(spec));
    spec.seed = 2;
    spec.with_position = false;
    write_text_file(dir_.file("canvas_2.xml"), sample_recording_xml(spec));
    spec.material = "Cork";
    write_text_file(dir_.file("cork.xml"), sample_recording_xml(spec));
    const CommandResult r = run_haptex({"convert", "hatt", dir_.path().string(), "-o", file_});
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  TempDir dir_;
  TempDir out_;
  std::string file_ = out_.file("recordings.h5");
};

TEST_F(ConvertedFile, InfoPrintsMaterialsRecordingsAndUnits) {
  const CommandResult r = run_haptex({"info", file_, "-v"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("recordings/1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("sample_canvas (Sample Canvas)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("recordings: 2"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("0.50 s at 10000 Hz"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("m/s^2"), std::string::npos) << r.out;
  const CommandResult brief = run_haptex({"info", file_});
  EXPECT_NE(brief.out.find("0.50 s at 10000 Hz  [accel, accel_xyz,"), std::string::npos) << brief.out;
  EXPECT_EQ(brief.out.find("m/s^2"), std::string::npos) << "units only with -v: " << brief.out;
}

TEST_F(ConvertedFile, InfoJsonFollowsItsSchema) {
  const CommandResult r = run_haptex({"info", file_, "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json doc = nlohmann::json::parse(r.out);
  EXPECT_NO_THROW(json::validate(doc, "info.schema.json", "info output"));
  ASSERT_EQ(doc["materials"].size(), 2u);
  EXPECT_EQ(doc["materials"][0]["id"], "cork");
  const auto& recordings = doc["materials"][1]["collections"]["recordings"];
  ASSERT_EQ(recordings.size(), 2u);
  EXPECT_DOUBLE_EQ(recordings[0]["duration_s"].get<double>(), 0.5);
  EXPECT_EQ(recordings[0]["datasets"].size(), 8u);  // with position
  EXPECT_EQ(recordings[1]["datasets"].size(), 7u);  // without

  nlohmann::json broken = doc;
  broken["materials"][0]["id"] = "Not An Id";
  EXPECT_THROW(json::validate(broken, "info.schema.json", "info output"), Error);
}

// Issue 32: info shows any haptex file, and says when this haptex cannot read it and why.
TEST_F(ConvertedFile, InfoSaysWhyAFormatCannotBeRead) {
  if (!python_has("h5py")) GTEST_SKIP() << "python3-h5py is not installed (make deps installs it)";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"recordings/1", ""},
      {"recordings/9", "written by a newer haptex: this one reads recordings/1"},
      {"recordings/01", "no version haptex writes: the attribute was edited or damaged"},
      {"dataset/3", "an older version: this haptex reads dataset/4, which haptex align writes"},
      {"spectra/1", "no kind of file haptex writes"},
      // Review 16, F4: a version of 50 000 digits overflowed the stack of the pattern match; F7: any
      // version above this haptex's is newer, 2^31 and beyond too, and a kind edited is a kind edited.
      {"recordings/" + std::string(50000, '9'), "written by a newer haptex: this one reads recordings/1"},
      {"recordings/2147483648", "written by a newer haptex: this one reads recordings/1"},
      {" recordings/1", "no version haptex writes: the attribute was edited or damaged"},
      {"Recordings/1", "no version haptex writes: the attribute was edited or damaged"},
      {"recordings", "no version haptex writes: the attribute was edited or damaged"},
      {"recordings/", "no version haptex writes: the attribute was edited or damaged"}};
  for (const auto& [format, remark] : cases) {
    const CommandResult edit = run_python({"-c", "import h5py, sys; h5py.File(sys.argv[1], 'a').attrs['haptex_format'] = sys.argv[2]",
                                           file_, format});
    ASSERT_EQ(edit.exit_code, 0) << edit.err;
    const CommandResult text = run_haptex({"info", file_}), json = run_haptex({"info", file_, "--json"});
    ASSERT_EQ(text.exit_code, 0) << text.err;
    ASSERT_EQ(json.exit_code, 0) << json.err;
    // A format of more than 80 bytes is quoted by its first 80 and its length (review 17, F6).
    const std::string quoted = format.size() > 80 ? format.substr(0, 80) + "... (" + std::to_string(format.size()) + " bytes)" : format;
    const std::string shown = "format   " + quoted + (remark.empty() ? "," : " (" + remark + "),");
    EXPECT_NE(text.out.find(shown), std::string::npos) << text.out;
    const nlohmann::json doc = nlohmann::json::parse(json.out);
    EXPECT_NO_THROW(json::validate(doc, "info.schema.json", "info output")) << format;
    EXPECT_EQ(doc.value("format_remark", ""), remark);
  }
}

// Review 16, F6: a format written as an ASCII string (older h5py, other HDF5 tools) is read, and one
// whose bytes are not UTF-8 is shown escaped with its remark, not refused as "not a string".
TEST_F(ConvertedFile, InfoShowsAFormatInAnyCharacterSet) {
  if (!python_has("h5py")) GTEST_SKIP() << "python3-h5py is not installed (make deps installs it)";
  const std::string write =
      "import h5py, os, sys; f = h5py.File(sys.argv[1], 'a'); value = os.fsencode(sys.argv[3]);\n"
      "kind = {'ascii': h5py.string_dtype('ascii'), 'fixed': 'S%d' % len(value)}[sys.argv[2]]\n"
      "f.attrs.create('haptex_format', value, dtype=kind)";
  struct Case {
    std::string kind, format, shown, remark;
  };
  const std::vector<Case> cases = {
      {"ascii", "recordings/1", "recordings/1", ""},
      {"ascii", "recordings/\xff", "recordings/\\xff", "no version haptex writes: the attribute was edited or damaged"},
      {"fixed", "recordings/\xff\xfe", "recordings/\\xff\\xfe", "no version haptex writes: the attribute was edited or damaged"}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.kind + " " + c.shown);
    const CommandResult edit = run_python({"-c", write, file_, c.kind, c.format});
    ASSERT_EQ(edit.exit_code, 0) << edit.err;
    const CommandResult text = run_haptex({"info", file_}), json = run_haptex({"info", file_, "--json"});
    ASSERT_EQ(text.exit_code, 0) << text.err;
    ASSERT_EQ(json.exit_code, 0) << json.err;
    EXPECT_NE(text.out.find("format   " + c.shown + (c.remark.empty() ? "," : " (" + c.remark + "),")), std::string::npos) << text.out;
    const nlohmann::json doc = nlohmann::json::parse(json.out);
    EXPECT_NO_THROW(json::validate(doc, "info.schema.json", "info output"));
    EXPECT_EQ(doc.value("format_remark", ""), c.remark);
  }
  // A format of 100 000 bytes is quoted by its start and length, not whole (review 17, F6).
  ASSERT_EQ(run_python({"-c", write, file_, "ascii", "recordings/1" + std::string(100000, 'x')}).exit_code, 0);
  const CommandResult huge = run_haptex({"trajectory", file_, "--material", "cork", "-o", out_.file("huge.csv")});
  EXPECT_EQ(huge.exit_code, 2);
  EXPECT_LT(huge.err.size(), 1000u) << huge.err.substr(0, 300);
  EXPECT_NE(huge.err.find("(100012 bytes)"), std::string::npos) << huge.err.substr(0, 300);
  // The current format in ASCII is the current format for every reader, not only info.
  ASSERT_EQ(run_python({"-c", write, file_, "ascii", "recordings/1"}).exit_code, 0);
  const CommandResult stroke = run_haptex({"trajectory", file_, "--material", "cork", "-o", out_.file("stroke.csv")});
  EXPECT_EQ(stroke.exit_code, 0) << stroke.err;
}

TEST_F(ConvertedFile, InfoRefusesFilesHaptexDidNotWrite) {
  write_text_file(out_.file("plain.txt"), "hello");
  const CommandResult r = run_haptex({"info", out_.file("plain.txt")});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("not an HDF5 file"), std::string::npos) << r.err;
}

TEST_F(ConvertedFile, H5pyReadsTheDocumentedLayout) {
  if (!python_has("h5py"))
    GTEST_SKIP() << "python3-h5py is not installed (make deps installs it)";
  const std::string script = std::string(HAPTEX_SCHEMA_DIR) + "/../tests/e2e/check_layout.py";
  const std::string layout = std::string(HAPTEX_SCHEMA_DIR) + "/hdf5-layout.md";
  const CommandResult ok = run_python({script, layout, file_, "Recordings"});
  EXPECT_EQ(ok.exit_code, 0) << ok.out << ok.err;
  EXPECT_NE(ok.out.find("layout ok"), std::string::npos) << ok.out << ok.err;

  // The checker itself must catch a file that breaks the layout.
  const CommandResult broken = run_python(
      {"-c",
       "import h5py, sys; f = h5py.File(sys.argv[1], 'r+'); del f['/materials/cork/recordings/0/speed_lp']; "
       "f['/materials/cork/recordings/0/accel'].attrs['units'] = 'g'",
       file_});
  ASSERT_EQ(broken.exit_code, 0) << broken.err;
  const CommandResult bad = run_python({script, layout, file_, "Recordings"});
  EXPECT_EQ(bad.exit_code, 1) << bad.out;
  EXPECT_NE(bad.out.find("missing: /materials/cork/recordings/0/speed_lp"), std::string::npos) << bad.out;
  EXPECT_NE(bad.out.find("units 'g'"), std::string::npos) << bad.out;
}

}  // namespace
}  // namespace haptex::test
