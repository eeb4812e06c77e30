#include "convert/hatt_recording_reader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "convert/csv_recording_reader.hpp"
#include "core/error.hpp"
#include "core/gzip.hpp"
#include "core/sha256.hpp"
#include "core/text/format.hpp"
#include "tests/support/bad_input.hpp"
#include "tests/support/sample_recording.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::convert {
namespace {

using test::bad_input_message;
using test::SampleRecordingSpec;
using test::TempDir;
using text::replace_all;

TEST(HattRecordingReader, ReadsTheDefaultFormat) {
  TempDir dir;
  SampleRecordingSpec spec;
  spec.seconds = 0.5;
  const std::string path = dir.file("canvas.xml");
  test::write_text_file(path, test::sample_recording_xml(spec));
  const Recording r = read_hatt_recording_xml(path, default_field_map());
  EXPECT_EQ(r.material, "Sample Canvas");
  EXPECT_EQ(r.texture, 7);
  EXPECT_EQ(r.sample_rate_hz, 10000.0);
  EXPECT_EQ(r.samples(), 5000u);
  EXPECT_EQ(r.channels.size(), 9u);
  EXPECT_EQ(r.units.at("accel"), "m/s^2");
  EXPECT_EQ(r.source_sha256.size(), 64u);
  const auto expected = test::make_sample_channels(spec);
  for (std::size_t i = 0; i < r.samples(); i += 97) {
    EXPECT_NEAR(r.channels.at("accel_y")[i], expected.accel_y[i], 5e-7);
    EXPECT_NEAR(r.channels.at("speed")[i], expected.speed[i], 5e-7);
    EXPECT_NEAR(r.channels.at("position_z")[i], expected.position_z[i], 5e-7);
  }
}

TEST(HattRecordingReader, OptionalChannelsMayBeAbsent) {
  TempDir dir;
  SampleRecordingSpec spec;
  spec.seconds = 0.2;
  spec.with_position = false;
  spec.with_tangential_force = false;
  test::write_text_file(dir.file("a.xml"), test::sample_recording_xml(spec));
  const Recording r = read_hatt_recording_xml(dir.file("a.xml"), default_field_map());
  EXPECT_FALSE(r.has("position_x"));
  EXPECT_FALSE(r.has("force_tangential"));
  EXPECT_TRUE(r.has("force_normal"));
}

TEST(HattRecordingReader, FieldMapPointsAtOtherElementNames) {
  TempDir dir;
  SampleRecordingSpec spec;
  spec.seconds = 0.2;
  std::string xml = test::sample_recording_xml(spec);
  xml = replace_all(xml, "accelX", "acc_x");
  xml = replace_all(xml, "recordedData", "trial");
  xml = replace_all(xml, "<value>", "<v>");
  xml = replace_all(xml, "</value>", "</v>");
  test::write_text_file(dir.file("renamed.xml"), xml);
  EXPECT_NE(bad_input_message([&] { read_hatt_recording_xml(dir.file("renamed.xml"), default_field_map()); }).find("<trial>"),
            std::string::npos);

  FieldMap map = default_field_map();
  std::string map_json = R"({"root": "trial", "material": "material", "sample_rate": "SampleRate", "value": "v",
    "csv_time_column": "time_s",
    "units": {"accel": "AccelUnits", "force": "ForceUnits", "speed": "SpeedUnits"},
    "channels": {"accel_x": "acc_x", "accel_y": "accelY", "accel_z": "accelZ", "force_normal": "forceNormal",
                 "speed": "speed"}})";
  test::write_text_file(dir.file("map.json"), map_json);
  const Recording r = read_hatt_recording_xml(dir.file("renamed.xml"), load_field_map(dir.file("map.json")));
  EXPECT_EQ(r.samples(), 2000u);
  EXPECT_TRUE(r.has("accel_x"));
  EXPECT_FALSE(r.has("position_x"));  // this map does not name positions
}

TEST(HattRecordingReader, InvalidFieldMapIsRefusedWithItsPlace) {
  TempDir dir;
  test::write_text_file(dir.file("map.json"), R"({"root": "x", "material": "m", "sample_rate": "r", "value": "v",
    "csv_time_column": "t", "units": {"accel": "a", "force": "f", "speed": "s"},
    "channels": {"accel_x": "ax", "accel_y": "ay", "accel_z": 3, "force_normal": "f", "speed": "s"}})");
  const std::string message = bad_input_message([&] { load_field_map(dir.file("map.json")); });
  EXPECT_NE(message.find("map.json"), std::string::npos);
  EXPECT_NE(message.find("/channels/accel_z"), std::string::npos) << message;
  test::write_text_file(dir.file("broken.json"), "{\"root\": ");
  EXPECT_NE(bad_input_message([&] { load_field_map(dir.file("broken.json")); }).find("not valid JSON"), std::string::npos);
}

TEST(HattRecordingReader, ConvertsKnownUnitsAndRefusesUnknownOnes) {
  TempDir dir;
  SampleRecordingSpec spec;
  spec.seconds = 0.2;
  const std::string xml = test::sample_recording_xml(spec);
  test::write_text_file(dir.file("g.xml"), replace_all(xml, "<AccelUnits>m/s^2<", "<AccelUnits>g<"));
  const Recording in_g = read_hatt_recording_xml(dir.file("g.xml"), default_field_map());
  const auto expected = test::make_sample_channels(spec);
  EXPECT_NEAR(in_g.channels.at("accel_x")[10], 9.80665 * expected.accel_x[10], 1e-5);
  EXPECT_EQ(in_g.units.at("accel"), "m/s^2");

  test::write_text_file(dir.file("lbf.xml"), replace_all(xml, "<ForceUnits>N<", "<ForceUnits>lbf<"));
  const std::string message = bad_input_message([&] { read_hatt_recording_xml(dir.file("lbf.xml"), default_field_map()); });
  EXPECT_NE(message.find("unknown force unit 'lbf'"), std::string::npos) << message;
  EXPECT_NE(message.find("<ForceUnits> at line 6"), std::string::npos) << message;
}

TEST(HattRecordingReader, LineNumbersCountNewlinesInsideTags) {
  // In-place parsing overwrites some newlines; the reported line must still be the real one.
  TempDir dir;
  SampleRecordingSpec spec;
  spec.seconds = 0.2;
  std::string xml = replace_all(test::sample_recording_xml(spec), "<value>", "<value\n>");
  const auto speed = xml.find("<speed");
  const auto value = xml.find("<value", speed + 10);
  const auto text = xml.find('>', value) + 1;
  xml.replace(text, xml.find('<', text) - text, "oops");
  test::write_text_file(dir.file("split.xml"), xml);
  const std::size_t line = 1 + std::count(xml.begin(), xml.begin() + std::ptrdiff_t(value), '\n');
  const std::string message = bad_input_message([&] { read_hatt_recording_xml(dir.file("split.xml"), default_field_map()); });
  EXPECT_NE(message.find("<value> at line " + std::to_string(line) + " "), std::string::npos) << message;
}

TEST(HattRecordingReader, TextureNumberMustBeAnInteger) {
  TempDir dir;
  SampleRecordingSpec spec;
  spec.seconds = 0.2;
  test::write_text_file(dir.file("t.xml"), replace_all(test::sample_recording_xml(spec), "texture=\"7\"", "texture=\"abc\""));
  EXPECT_NE(bad_input_message([&] { read_hatt_recording_xml(dir.file("t.xml"), default_field_map()); }).find("texture=\"abc\" is not an integer"),
            std::string::npos);
}

TEST(HattRecordingReader, TooShortRecordingIsRefused) {
  TempDir dir;
  SampleRecordingSpec spec;
  spec.seconds = 0.05;
  test::write_text_file(dir.file("short.xml"), test::sample_recording_xml(spec));
  EXPECT_NE(bad_input_message([&] { read_hatt_recording_xml(dir.file("short.xml"), default_field_map()); }).find("only 500 samples"),
            std::string::npos);
}

TEST(CsvRecordingReader, ReadsColumnsAndDerivesTheRate) {
  TempDir dir;
  SampleRecordingSpec spec;
  spec.seconds = 0.3;
  test::write_text_file(dir.file("Cork_2.csv"), test::sample_recording_csv(spec));
  const Recording r = read_csv_recording(dir.file("Cork_2.csv"), default_field_map());
  EXPECT_EQ(r.material, "Cork");
  EXPECT_NEAR(r.sample_rate_hz, 10000.0, 1e-3);
  EXPECT_EQ(r.samples(), 3000u);
  EXPECT_EQ(r.channels.size(), 5u);
  EXPECT_NEAR(r.channels.at("force_normal")[42], test::make_sample_channels(spec).force_normal[42], 5e-7);
}

TEST(CsvRecordingReader, MaterialNameFromFileName) {
  EXPECT_EQ(material_from_file_stem("Cork_2"), "Cork");
  EXPECT_EQ(material_from_file_stem("Brick 2"), "Brick 2");
  EXPECT_EQ(material_from_file_stem("sandpaper-100-3"), "sandpaper-100");
  EXPECT_EQ(material_from_file_stem("felt"), "felt");
}

TEST(CsvRecordingReader, RefusesRaggedRowsBadValuesAndGaps) {
  TempDir dir;
  SampleRecordingSpec spec;
  spec.seconds = 0.2;
  const std::string csv = test::sample_recording_csv(spec);
  std::string ragged = csv;
  ragged.insert(ragged.find('\n', ragged.find('\n', ragged.find('\n') + 1) + 1), ",5");  // line 3
  test::write_text_file(dir.file("ragged.csv"), ragged);
  EXPECT_NE(bad_input_message([&] { read_csv_recording(dir.file("ragged.csv"), default_field_map()); })
                .find("line 3: has 7 fields but the header has 6"),
            std::string::npos);

  std::string nan = csv;
  const auto line5 = nan.find('\n', nan.find('\n', nan.find('\n', nan.find('\n') + 1) + 1) + 1) + 1;
  nan.replace(nan.find(',', line5) + 1, nan.find(',', nan.find(',', line5) + 1) - nan.find(',', line5) - 1, "nan");
  test::write_text_file(dir.file("nan.csv"), nan);
  const std::string message = bad_input_message([&] { read_csv_recording(dir.file("nan.csv"), default_field_map()); });
  EXPECT_NE(message.find("line 5, column 'accelX'"), std::string::npos) << message;
  EXPECT_NE(message.find("NaN or Inf"), std::string::npos) << message;

  // A stamp that wanders by 3 % of a step is interpolated over (docs/convert.md, "Sources at other
  // rates"); five rows missing are a gap no interpolation fills.
  test::write_text_file(dir.file("jitter.csv"), replace_all(csv, "0.010000,", "0.010003,"));
  const Recording jittered = read_csv_recording(dir.file("jitter.csv"), default_field_map());
  EXPECT_EQ(jittered.samples(), 2000u);
  EXPECT_EQ(jittered.source_texts.count("resampled"), 1u);
  std::string gap = csv;
  const auto row = gap.find("0.010000,");
  gap.erase(row, gap.find("0.010500,") - row);
  test::write_text_file(dir.file("gap.csv"), gap);
  const std::string dropped = bad_input_message([&] { read_csv_recording(dir.file("gap.csv"), default_field_map()); });
  EXPECT_NE(dropped.find("a gap of 0.0006"), std::string::npos) << dropped;
  EXPECT_NE(dropped.find("samples were dropped"), std::string::npos) << dropped;

  test::write_text_file(dir.file("notime.csv"), replace_all(csv, "time_s", "t"));
  EXPECT_NE(bad_input_message([&] { read_csv_recording(dir.file("notime.csv"), default_field_map()); }).find("no 'time_s' column"),
            std::string::npos);
}

}  // namespace
}  // namespace haptex::convert

namespace haptex::convert {
namespace {

// A gzip-compressed recording reads as the plain one; provenance names the file as it is on disk.
TEST(HattRecordingReader, ReadsGzipCompressedFiles) {
  test::TempDir dir;
  test::SampleRecordingSpec spec;
  spec.seconds = 0.3;
  const std::string xml = test::sample_recording_xml(spec);
  test::write_text_file(dir.file("a.xml"), xml);
  test::write_recording_text(dir.file("a.xml.gz"), xml);
  const Recording plain = read_hatt_recording_xml(dir.file("a.xml"), default_field_map());
  const Recording packed = read_hatt_recording_xml(dir.file("a.xml.gz"), default_field_map());
  EXPECT_EQ(packed.channels, plain.channels);
  EXPECT_EQ(packed.material, plain.material);
  EXPECT_EQ(packed.source_sha256, plain.source_sha256) << "the hash is the XML text's, compressed or not";
  EXPECT_EQ(plain.source_sha256, sha256_file(dir.file("a.xml")));
  // Known by its content, not its name.
  std::filesystem::rename(dir.file("a.xml.gz"), dir.file("b.xml"));
  EXPECT_EQ(read_hatt_recording_xml(dir.file("b.xml"), default_field_map()).channels, plain.channels);
}

TEST(HattRecordingReader, DamagedOrHugeGzipIsRefusedNamingTheFile) {
  test::TempDir dir;
  test::SampleRecordingSpec spec;
  spec.seconds = 0.3;
  const std::string gz = gzip::compress(test::sample_recording_xml(spec), 1);
  test::write_text_file(dir.file("cut.xml.gz"), gz.substr(0, gz.size() / 2));
  std::string m = test::bad_input_message([&] { read_hatt_recording_xml(dir.file("cut.xml.gz"), default_field_map()); });
  EXPECT_NE(m.find(dir.file("cut.xml.gz")), std::string::npos) << m;
  EXPECT_NE(m.find("cut short"), std::string::npos) << m;
  // The limit applies to what the file expands to, not only to its size on disk.
  test::write_text_file(dir.file("big.xml.gz"), gz);
  m = test::bad_input_message([&] { read_hatt_recording_xml(dir.file("big.xml.gz"), default_field_map(), gz.size() * 2); });
  EXPECT_NE(m.find("decompresses to more than the limit"), std::string::npos) << m;
  // What the gzip holds is checked like any XML.
  test::write_recording_text(dir.file("bad.xml.gz"), "<recordedData><material>Caf\xe9</material>");
  m = test::bad_input_message([&] { read_hatt_recording_xml(dir.file("bad.xml.gz"), default_field_map()); });
  EXPECT_NE(m.find("malformed XML"), std::string::npos) << m;
}

}  // namespace
}  // namespace haptex::convert
