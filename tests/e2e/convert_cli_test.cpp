// `haptex convert hatt` as a user runs it: good input, and every kind of bad input the issue lists,
// each refused with exit code 2, a message naming the file, the place and the fix, and no output left.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "core/temporary_name.hpp"
#include "tests/support/run_haptex.hpp"
#include "tests/support/sample_recording.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {

std::string good_xml(double seconds = 0.3) {
  SampleRecordingSpec spec;
  spec.seconds = seconds;
  return sample_recording_xml(spec);
}

std::string replace_first(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  if (at == std::string::npos) throw std::runtime_error("fixture text not found: " + from);
  return text.replace(at, from.size(), to);
}

std::string remove_between(std::string text, const std::string& open, const std::string& close) {
  const auto start = text.find(open);
  const auto end = text.find(close, start);
  return text.erase(start, end + close.size() - start);
}

class BadInput : public ::testing::Test {
 protected:
  // Runs convert on one file with this content and checks the refusal.
  void expect_refused(const std::string& content, const std::vector<std::string>& message_parts,
                      std::vector<std::string> extra_args = {}) {
    const std::string input = dir_.file("input.xml");
    write_text_file(input, content);
    std::vector<std::string> args = {"convert", "hatt", input, "-o", output_};
    args.insert(args.end(), extra_args.begin(), extra_args.end());
    const CommandResult r = run_haptex(args);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("input.xml"), std::string::npos) << "message does not name the file: " << r.err;
    for (const auto& part : message_parts) EXPECT_NE(r.err.find(part), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one clear message: " << r.err;
    EXPECT_FALSE(std::filesystem::exists(output_)) << "output left behind";
    EXPECT_TRUE(temporaries_of(output_).empty()) << "partial output left behind";
  }

  TempDir dir_;
  std::string output_ = dir_.file("out.h5");
};

TEST(ConvertCli, ConvertsAFolderAndPrintsASummary) {
  TempDir dir;
  std::filesystem::create_directory(dir.path() / "xml");
  write_text_file(dir.file("xml/a.xml"), good_xml());
  SampleRecordingSpec csv_spec;
  csv_spec.seconds = 0.3;
  write_text_file(dir.file("xml/Cork_1.csv"), sample_recording_csv(csv_spec));
  const CommandResult r = run_haptex({"convert", "hatt", dir.file("xml"), "-o", dir.file("r.h5")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("2 recordings"), std::string::npos) << r.out;
  EXPECT_TRUE(only_progress_lines(r.err)) << "no bar redrawn in place where stderr is a log: " << r.err;
  EXPECT_NE(r.err.find("convert: 2/2 "), std::string::npos) << "a line when it ends: " << r.err;
  const CommandResult json = run_haptex({"convert", "hatt", dir.file("xml"), "-o", dir.file("r.h5"), "--force", "--json"});
  ASSERT_EQ(json.exit_code, 0) << json.err;
  EXPECT_NE(json.out.find("\"material_id\": \"cork\""), std::string::npos) << json.out;
}

TEST_F(BadInput, TruncatedXml) {
  const std::string xml = good_xml();
  expect_refused(xml.substr(0, xml.size() * 6 / 10), {"malformed XML", "line ", "truncated"});
}

TEST_F(BadInput, MissingChannel) {
  expect_refused(remove_between(good_xml(), "<accelY", "</accelY>"), {"<accelY>", "missing", "--map"});
}

TEST_F(BadInput, ChannelsOfDifferentLengths) {
  std::string xml = good_xml();
  const auto force = xml.find("<forceNormal");
  const auto value = xml.find("<value>", force);
  xml.erase(value, xml.find('\n', value) + 1 - value);
  expect_refused(xml, {"<forceNormal> at line", "2999 samples", "3000"});
}

TEST_F(BadInput, NaNValue) {
  std::string xml = good_xml();
  const auto value = xml.find("<value>", xml.find("<speed"));
  xml.replace(value, xml.find("</value>", value) - value, "<value>nan");
  expect_refused(xml, {"<value> at line", "value 1 of <speed>", "NaN or Inf", "interpolate"});
}

TEST_F(BadInput, InfValue) {
  std::string xml = good_xml();
  const auto value = xml.find("<value>", xml.find("<accelZ"));
  xml.replace(value, xml.find("</value>", value) - value, "<value>-inf");
  expect_refused(xml, {"of <accelZ>", "NaN or Inf"});
}

TEST_F(BadInput, NotANumber) {
  std::string xml = good_xml();
  const auto value = xml.find("<value>", xml.find("<accelX"));
  xml.replace(value, xml.find("</value>", value) - value, "<value>1.2.3");
  expect_refused(xml, {"'1.2.3' is not a number"});
}

TEST_F(BadInput, ASampleRateTooLowOrNotWholeHz) {
  expect_refused(replace_first(good_xml(), "<SampleRate>10000<", "<SampleRate>1000<"),
                 {"<SampleRate> at line 4", "1000 Hz", "at least 2 kHz"});
  expect_refused(replace_first(good_xml(), "<SampleRate>10000<", "<SampleRate>44100.5<"),
                 {"<SampleRate> at line 4", "44100.5 Hz", "whole Hz"});
}

TEST_F(BadInput, MissingSampleRate) {
  expect_refused(remove_between(good_xml(), "<SampleRate>", "</SampleRate>"),
                 {"<SampleRate> is missing", "10 kHz"});
}

TEST_F(BadInput, DtdAndEntityDeclarationsAreRefused) {
  const std::string xml = good_xml();
  const std::string with_dtd = replace_first(
      xml, "<recordedData", "<!DOCTYPE recordedData [<!ENTITY boom \"ha\">]>\n<recordedData");
  expect_refused(replace_first(with_dtd, "<material>Sample Canvas", "<material>&boom;"),
                 {"DTD or entity declaration", "line 2", "never expands entities"});
}

TEST_F(BadInput, FileOverTheSizeLimitIsRefusedBeforeParsing) {
  // Not even XML: the size check must come first.
  expect_refused(std::string(5000, 'x'), {"5000 bytes", "limit of 4096", "--max-bytes"}, {"--max-bytes", "4096"});
}

TEST_F(BadInput, WrongRootElement) {
  expect_refused(replace_first(replace_first(good_xml(), "<recordedData", "<modelSet"), "</recordedData>",
                               "</modelSet>"),
                 {"<modelSet>", "not <recordedData>"});
}

TEST(ConvertCli, UnwritableOutputDirectoryIsRefused) {
  TempDir dir;
  write_text_file(dir.file("a.xml"), good_xml());
  std::string out_dir = dir.file("locked");
  std::filesystem::create_directory(out_dir);
  std::filesystem::permissions(out_dir, std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
  if (geteuid() == 0) {
    // Root writes anywhere permissions are concerned; /proc refuses new files even to root, where
    // the sandbox lets us see that.
    out_dir = "/proc/self";
    if (FILE* probe = std::fopen("/proc/self/haptex-probe", "w")) {
      std::fclose(probe);
      GTEST_SKIP() << "running as root and /proc/self is writable here: no unwritable directory to test with";
    }
  }
  const std::string output = out_dir + "/r.h5";
  const CommandResult r = run_haptex({"convert", "hatt", dir.file("a.xml"), "-o", output});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(output), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("directory you can write to"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(output));
}

TEST(ConvertCli, ExistingOutputIsRefusedUnlessForcedAndHaptexsOwn) {
  TempDir dir;
  write_text_file(dir.file("a.xml"), good_xml());
  write_text_file(dir.file("r.h5"), "precious");
  const CommandResult refused = run_haptex({"convert", "hatt", dir.file("a.xml"), "-o", dir.file("r.h5")});
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("already exists"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("--force"), std::string::npos) << refused.err;
  std::ifstream kept(dir.file("r.h5"));
  std::string content;
  kept >> content;
  EXPECT_EQ(content, "precious");
  // --force replaces only a file haptex wrote: not the user's "precious", but a recordings file.
  const CommandResult not_ours = run_haptex({"convert", "hatt", dir.file("a.xml"), "-o", dir.file("r.h5"), "--force"});
  EXPECT_EQ(not_ours.exit_code, 2);
  EXPECT_NE(not_ours.err.find("--force replaces only a file haptex wrote"), std::string::npos) << not_ours.err;
  std::filesystem::remove(dir.file("r.h5"));
  ASSERT_EQ(run_haptex({"convert", "hatt", dir.file("a.xml"), "-o", dir.file("r.h5")}).exit_code, 0);
  const CommandResult forced = run_haptex({"convert", "hatt", dir.file("a.xml"), "-o", dir.file("r.h5"), "--force"});
  EXPECT_EQ(forced.exit_code, 0) << forced.err;
}

TEST(ConvertCli, NamingAFileTwiceMakesOneRecording) {
  TempDir dir;
  write_text_file(dir.file("a.xml"), good_xml());
  const CommandResult r = run_haptex({"convert", "hatt", dir.file("a.xml"), dir.path().string(), "-o", dir.file("r.h5")});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("1 recordings"), std::string::npos) << r.out;
}

TEST(ConvertCli, BadUsageExitsWithTwo) {
  EXPECT_EQ(run_haptex({"convert", "hatt", "x.xml", "-o", "/tmp/x.h5", "--max-bytes", "-5"}).exit_code, 2);
  const CommandResult map_dir = run_haptex({"convert", "hatt", "x.xml", "-o", "/tmp/x.h5", "--map", "/tmp"});
  EXPECT_EQ(map_dir.exit_code, 2) << map_dir.err;
  EXPECT_EQ(run_haptex({"convert", "hatt"}).exit_code, 2);
  EXPECT_EQ(run_haptex({"frobnicate"}).exit_code, 2);
  const CommandResult missing = run_haptex({"convert", "hatt", "/no/such/file.xml", "-o", "/tmp/x.h5"});
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("/no/such/file.xml"), std::string::npos);
  EXPECT_EQ(run_haptex({"--help"}).exit_code, 0);
}

}  // namespace
}  // namespace haptex::test
