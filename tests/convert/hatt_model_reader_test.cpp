#include "convert/hatt_model_reader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "core/error.hpp"
#include "tests/support/npy.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::convert {
namespace {

// Three AR(2) models, one triangle, laid out one element per line like the published files.
constexpr const char* kGood = R"(<?xml version="1.0" encoding="utf-8"?>
<modelSet texture="7">
   <material>Tiny</material>
   <AccelUnits>m/s^2</AccelUnits>
   <SpeedUnits>mm/s</SpeedUnits>
   <ForceUnits>N</ForceUnits>
   <SampleRate>10000</SampleRate>
   <mu>0.25</mu>
   <numMod>3</numMod>
   <numTri>1</numTri>
   <maxSpeed>200.5</maxSpeed>
   <maxForce>3.5</maxForce>
   <speedList type="array">
      <value>0.000000</value>
      <value>200.500000</value>
      <value>200.500000</value>
   </speedList>
   <forceList type="array">
      <value>0.000000</value>
      <value>0.000000</value>
      <value>3.500000</value>
   </forceList>
   <tri type="array">
      <value>1</value>
      <value>2</value>
      <value>3</value>
   </tri>
   <numARCoeff>2</numARCoeff>
   <numMACoeff>0</numMACoeff>
   <model>
      <modNum>1</modNum>
      <ARcoeff><value>1</value><value>-0.5</value><value>0.3</value></ARcoeff>
      <ARlsf><value>0.8</value><value>1.4</value></ARlsf>
      <MAcoeff><value>1.0</value></MAcoeff>
      <MAlsf/>
      <var>0.000000</var>
      <speedMod>0.000000</speedMod>
      <forceMod>0.000000</forceMod>
   </model>
   <model>
      <modNum>2</modNum>
      <ARcoeff><value>1</value><value>-0.6</value><value>0.2</value></ARcoeff>
      <ARlsf><value>0.7</value><value>1.5</value></ARlsf>
      <var>0.000000</var>
      <speedMod>200.500000</speedMod>
      <forceMod>0.000000</forceMod>
   </model>
   <model>
      <modNum>3</modNum>
      <ARcoeff><value>1</value><value>-0.7</value><value>0.1</value></ARcoeff>
      <ARlsf><value>0.6</value><value>1.6</value></ARlsf>
      <var>0.125</var>
      <gain>2.5</gain>
      <speedMod>200.500000</speedMod>
      <forceMod>3.500000</forceMod>
   </model>
</modelSet>
)";

std::string replace_first(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "fixture lacks " << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// 1-based line of the first occurrence of needle.
std::size_t line_of(const std::string& text, const std::string& needle) {
  const std::size_t at = text.find(needle);
  return std::size_t(std::count(text.begin(), text.begin() + std::ptrdiff_t(at), '\n')) + 1;
}

void write(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

// Writes the XML to a temp file, reads it, and returns the (bad-input) error message.
std::string error_reading(const std::string& xml, std::string* path_out = nullptr) {
  test::TempDir dir;
  const std::string path = dir.file("Models_Bad.xml");
  write(path, xml);
  if (path_out) *path_out = path;
  try {
    read_hatt_model(path);
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::bad_input);
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << "message does not name the file: " << e.what();
    return e.what();
  }
  ADD_FAILURE() << "no error was thrown";
  return "";
}

void expect_has(const std::string& message, const std::string& fragment) {
  EXPECT_NE(message.find(fragment), std::string::npos) << "\"" << fragment << "\" not in: " << message;
}

TEST(HattModelReader, ReadsEveryField) {
  test::TempDir dir;
  const std::string path = dir.file("Models_Tiny.xml");
  write(path, kGood);
  const ar::ModelSet set = read_hatt_model(path);
  EXPECT_EQ(set.source, path);
  EXPECT_EQ(set.texture, 7);
  EXPECT_EQ(set.material, "Tiny");
  EXPECT_EQ(set.accel_units, "m/s^2");
  EXPECT_EQ(set.speed_units, "mm/s");
  EXPECT_EQ(set.force_units, "N");
  EXPECT_EQ(set.sample_rate_hz, 10000.0);
  EXPECT_EQ(set.mu, 0.25);
  EXPECT_EQ(set.max_speed, 200.5);
  EXPECT_EQ(set.max_force, 3.5);
  EXPECT_EQ(set.num_ar_coeff, 2);
  EXPECT_EQ(set.num_ma_coeff, 0);
  EXPECT_EQ(set.speed_list, (std::vector<double>{0.0, 200.5, 200.5}));
  EXPECT_EQ(set.force_list, (std::vector<double>{0.0, 0.0, 3.5}));
  ASSERT_EQ(set.triangles.size(), 1u);
  EXPECT_EQ(set.triangles[0], (std::array<std::size_t, 3>{0, 1, 2}));  // 1-based in the file
  ASSERT_EQ(set.models.size(), 3u);
  const ar::ArModel& m3 = set.models[2];
  EXPECT_EQ(m3.number, 3);
  EXPECT_EQ(m3.ar_coeff, (std::vector<double>{1.0, -0.7, 0.1}));
  EXPECT_EQ(m3.ar_lsf, (std::vector<double>{0.6, 1.6}));
  EXPECT_EQ(m3.variance, 0.125);
  EXPECT_EQ(m3.gain, 2.5);
  EXPECT_EQ(m3.speed, 200.5);
  EXPECT_EQ(m3.force, 3.5);
  EXPECT_FALSE(set.models[0].gain.has_value());
  EXPECT_EQ(set.models[0].ma_coeff, (std::vector<double>{1.0}));
  EXPECT_TRUE(set.models[0].ma_lsf.empty());
  EXPECT_NO_THROW(load_hatt_model(path));
}

TEST(HattModelReader, MissingFile) {
  test::TempDir dir;
  const std::string path = dir.file("Models_Nowhere.xml");
  try {
    read_hatt_model(path);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    expect_has(e.what(), path);
    expect_has(e.what(), "no such file");
  }
}

TEST(HattModelReader, MissingElement) {
  const std::string xml = replace_first(kGood, "   <maxForce>3.5</maxForce>\n", "");
  const std::string message = error_reading(xml);
  expect_has(message, "element <maxForce> is missing");
  expect_has(message, "<modelSet> at line 2");
  expect_has(message, "Add the <maxForce> element");
}

TEST(HattModelReader, MissingModelElement) {
  const std::string xml = replace_first(kGood, "      <var>0.125</var>\n", "");
  const std::string message = error_reading(xml);
  expect_has(message, "element <var> is missing");
  // The third <model> is where it is missing.
  const std::size_t third_model = line_of(xml, "<modNum>3</modNum>") - 1;
  expect_has(message, "<model> at line " + std::to_string(third_model));
}

TEST(HattModelReader, NumModDisagreesWithModels) {
  // Four vertices but three models: the <model> count is what disagrees.
  std::string xml = replace_first(kGood, "<numMod>3</numMod>", "<numMod>4</numMod>");
  xml = replace_first(xml, "      <value>200.500000</value>\n   </speedList>",
                      "      <value>200.500000</value>\n      <value>9</value>\n   </speedList>");
  xml = replace_first(xml, "      <value>3.500000</value>\n   </forceList>",
                      "      <value>3.500000</value>\n      <value>9</value>\n   </forceList>");
  const std::string message = error_reading(xml);
  expect_has(message, "<numMod> at line " + std::to_string(line_of(xml, "<numMod>")));
  expect_has(message, "says 4 but the file has 3 <model> elements");
}

TEST(HattModelReader, NumModDisagreesWithVertexList) {
  const std::string xml = replace_first(kGood, "<numMod>3</numMod>", "<numMod>2</numMod>");
  const std::string message = error_reading(xml);
  expect_has(message, "<numMod>");
  expect_has(message, "says 2 but the file has 3 <value> elements in <speedList>");
}

TEST(HattModelReader, NumTriDisagreesWithTriangles) {
  const std::string xml = replace_first(kGood, "<numTri>1</numTri>", "<numTri>2</numTri>");
  const std::string message = error_reading(xml);
  expect_has(message, "<numTri> at line " + std::to_string(line_of(xml, "<numTri>")));
  expect_has(message, "says 2 but the file has 1 <tri> elements");
}

TEST(HattModelReader, TriangleIndexOutOfRange) {
  for (const std::string bad : {"4", "0", "-1"}) {
    SCOPED_TRACE("index " + bad);
    const std::string xml = replace_first(kGood, "      <value>3</value>\n   </tri>", "      <value>" + bad + "</value>\n   </tri>");
    const std::string message = error_reading(xml);
    expect_has(message, "<value> at line " + std::to_string(line_of(xml, "<value>" + bad + "</value>\n   </tri>")));
    expect_has(message, "model index " + bad + " is outside 1..3");
  }
}

TEST(HattModelReader, TriangleWithTwoVertices) {
  const std::string xml = replace_first(kGood, "      <value>3</value>\n   </tri>", "   </tri>");
  expect_has(error_reading(xml), "a triangle has 2 vertices");
}

TEST(HattModelReader, NonNumericValue) {
  std::string xml = replace_first(kGood, "<value>200.500000</value>", "<value>fast</value>");
  std::string message = error_reading(xml);
  expect_has(message, "<value> at line " + std::to_string(line_of(xml, "fast")));
  expect_has(message, "'fast' is not a number");

  xml = replace_first(kGood, "<var>0.125</var>", "<var>0.125x</var>");
  message = error_reading(xml);
  expect_has(message, "<var> at line " + std::to_string(line_of(xml, "0.125x")));

  xml = replace_first(kGood, "<maxSpeed>200.5</maxSpeed>", "<maxSpeed></maxSpeed>");
  expect_has(error_reading(xml), "<maxSpeed> at line 11: '' is not a number");

  xml = replace_first(kGood, "<numMod>3</numMod>", "<numMod>3.5</numMod>");
  expect_has(error_reading(xml), "'3.5' is not an integer");
}

TEST(HattModelReader, TruncatedXml) {
  const std::string xml = std::string(kGood).substr(0, std::string(kGood).find("<modNum>2</modNum>"));
  const std::string message = error_reading(xml);
  expect_has(message, "malformed XML");
  expect_has(message, "truncated");
  expect_has(message, "line ");
}

TEST(HattModelReader, RefusesDoctypeAndEntities) {
  const std::string bomb = replace_first(kGood, "<modelSet texture=\"7\">",
                                         "<!DOCTYPE modelSet [\n  <!ENTITY lol \"lol\">\n  <!ENTITY lol2 \"&lol;&lol;&lol;\">\n]>\n"
                                         "<modelSet texture=\"7\">");
  const std::string with_use = replace_first(bomb, "<material>Tiny</material>", "<material>&lol2;</material>");
  std::string message = error_reading(with_use);
  expect_has(message, "line 2");
  expect_has(message, "DOCTYPE");
  expect_has(message, "never expands entities");

  const std::string external =
      replace_first(kGood, "<modelSet texture=\"7\">", "<!DOCTYPE modelSet SYSTEM \"file:///etc/passwd\">\n<modelSet texture=\"7\">");
  expect_has(error_reading(external), "DOCTYPE");
}

TEST(HattModelReader, LsfCountDisagreesWithOrder) {
  const std::string xml = replace_first(kGood, "<ARlsf><value>0.7</value><value>1.5</value></ARlsf>",
                                        "<ARlsf><value>0.7</value></ARlsf>");
  const std::string message = error_reading(xml);
  expect_has(message, "<ARlsf> at line " + std::to_string(line_of(xml, "<ARlsf><value>0.7</value></ARlsf>")));
  expect_has(message, "has 1 values but numARCoeff is 2");
}

TEST(HattModelReader, WrongRoot) {
  expect_has(error_reading("<?xml version=\"1.0\"?>\n<recordedData/>\n"), "the document element is not <modelSet>");
}

// Semantic problems the reader lets through are caught when the model is built, still naming the file.
TEST(HattModelReader, LoadChecksLsfOrder) {
  test::TempDir dir;
  const std::string path = dir.file("Models_Unsorted.xml");
  write(path, replace_first(kGood, "<value>0.6</value><value>1.6</value>", "<value>1.6</value><value>0.6</value>"));
  try {
    load_hatt_model(path);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    expect_has(e.what(), path);
    expect_has(e.what(), "model 3");
  }
}

TEST(HattModelReader, ReadsEveryPublishedModel) {
  const std::string shared = test::shared_data_dir();
  const std::filesystem::path dir = std::filesystem::path(shared) / "hatt" / "models";
  if (shared.empty() || !std::filesystem::is_directory(dir))
    GTEST_SKIP() << "../shared/data/hatt/models is absent: published HaTT models not read";
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    SCOPED_TRACE(entry.path().filename().string());
    const ar::PiecewiseArModel model = load_hatt_model(entry.path());
    const ar::ModelSet& set = model.set();
    EXPECT_EQ(set.sample_rate_hz, 10000.0);
    EXPECT_GE(model.order(), 14u);
    EXPECT_LE(model.order(), 20u);
    EXPECT_FALSE(set.material.empty());
    EXPECT_EQ(set.models.size(), set.speed_list.size());
    for (std::size_t i = 0; i < set.models.size(); ++i) {
      EXPECT_EQ(set.models[i].number, int(i) + 1);
      EXPECT_EQ(set.models[i].variance == 0.0, set.models[i].speed == 0.0 || set.models[i].force == 0.0);
    }
    ++files;
  }
  EXPECT_EQ(files, 60u);
}

}  // namespace
}  // namespace haptex::convert
