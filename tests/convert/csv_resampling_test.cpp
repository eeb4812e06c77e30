// Sources not at 10 kHz (docs/convert.md, "Sources at other rates") against scipy 1.10
// (tests/golden/resample_golden.py): a CSV at 6 kHz through resample_poly, a rig's log whose
// acceleration comes at irregular stamps in g and whose force and speed have their own 1 kHz time
// column, and an XML recording at 5 kHz.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "convert/csv_recording_reader.hpp"
#include "convert/field_map.hpp"
#include "convert/hatt_recording_reader.hpp"
#include "convert/resampling.hpp"
#include "core/error.hpp"
#include "tests/support/npy.hpp"
#include "tests/support/sample_recording.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::convert {
namespace {

using test::load_golden;
using test::max_scaled_error;

std::string cell(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

TEST(CsvResampling, A6kHzLogGoesThroughResamplePoly) {
  const std::vector<double> x = load_golden("resample/poly_x.npy").data;
  test::TempDir dir;
  std::ofstream csv(dir.file("cork_0.csv"));
  csv << "time_s,accelX,accelY,accelZ,forceNormal,speed\n";
  for (std::size_t i = 0; i < x.size(); ++i)
    csv << cell(double(i) / 6000.0) << "," << cell(x[i]) << ",0,0,1.5,40\n";
  csv.close();
  const Recording r = read_csv_recording(dir.file("cork_0.csv"), default_field_map());
  EXPECT_EQ(r.sample_rate_hz, 10000.0);
  EXPECT_LT(max_scaled_error(r.channels.at("accel_x"), load_golden("resample/poly_5_3.npy").data), 1e-12);
  EXPECT_NEAR(r.channels.at("force_normal")[800], 1.5, 1e-12) << "a steady force stays steady";
  EXPECT_NE(r.source_texts.at("resampled").find("from 6000 Hz"), std::string::npos);
}

TEST(CsvResampling, ChannelsWithTheirOwnTimesAndUnitsComeOntoOneGrid) {
  const std::vector<double> t = load_golden("resample/irregular_t.npy").data, x = load_golden("resample/irregular_x.npy").data;
  test::TempDir dir;
  nlohmann::json map = nlohmann::json::parse(std::ifstream(std::string(HAPTEX_SCHEMA_DIR) + "/hatt-recording-map.json"));
  map["csv_channel_times"] = {{"force_normal", "t_slow"}, {"speed", "t_slow"}};
  map["csv_units"] = {{"accel", "g"}};
  std::ofstream(dir.file("map.json")) << map.dump();
  // The slow channels start before the acceleration and end after it: the grid is the acceleration's.
  std::ofstream csv(dir.file("rig_0.csv"));
  csv << "time_s,accelX,accelY,accelZ,t_slow,forceNormal,speed\n";
  for (std::size_t i = 0; i < t.size(); ++i) {
    csv << cell(t[i]) << "," << cell(x[i]) << "," << cell(x[i]) << ",0,";
    const double slow = double(i) / 1000.0;
    if (slow <= t.back() + 0.01) csv << cell(slow) << "," << cell(2.0 + slow) << ",30\n";
    else csv << ",,\n";
  }
  csv.close();
  const Recording r = read_csv_recording(dir.file("rig_0.csv"), load_field_map(dir.file("map.json")));
  const double own = load_golden("resample/irregular_own_rate.npy").data.at(0);
  std::vector<double> expected = load_golden("resample/irregular_own_rate_10000.npy").data;
  for (double& v : expected) v *= 9.80665;
  expected.resize(r.samples());
  EXPECT_NEAR(double(r.samples()), std::floor((t.back() - t.front()) * 10000.0) + 1, 2.0);
  EXPECT_LT(max_scaled_error(r.channels.at("accel_x"), expected), 1e-12) << "at the stamps' own " << own << " Hz";
  EXPECT_EQ(r.channels.at("accel_y"), r.channels.at("accel_x"));
  // The force rises 1 N a second: at sample k of the grid (from t[0]) it is 2 + t[0] + k / 10000.
  const std::size_t k = r.samples() / 2;
  EXPECT_NEAR(r.channels.at("force_normal")[k], 2.0 + t.front() + double(k) / 10000.0, 1e-5);  // 10 uN
  EXPECT_NEAR(r.channels.at("speed")[k], 30.0, 1e-9);
}

TEST(CsvResampling, ASlowChannelsValueWithoutItsTimeIsRefused) {
  test::TempDir dir;
  nlohmann::json map = nlohmann::json::parse(std::ifstream(std::string(HAPTEX_SCHEMA_DIR) + "/hatt-recording-map.json"));
  map["csv_channel_times"] = {{"force_normal", "t_slow"}};
  std::ofstream(dir.file("map.json")) << map.dump();
  std::ofstream csv(dir.file("rig_0.csv"));
  csv << "time_s,accelX,accelY,accelZ,t_slow,forceNormal,speed\n";
  for (int i = 0; i < 2000; ++i) csv << cell(i / 10000.0) << ",0,0,0," << (i % 10 ? "," : cell(i / 10000.0) + ",") << "1,40\n";
  csv.close();
  try {
    read_csv_recording(dir.file("rig_0.csv"), load_field_map(dir.file("map.json")));
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("line 3: column 'forceNormal' has a value but its time column 't_slow' is empty"),
              std::string::npos)
        << e.what();
  }
}

// Review 9, C3: nanosecond stamps gave "the sample rate is 0 Hz" with "Give the rate in whole Hz".
TEST(CsvResampling, StampsThatAreNotSecondsSaySo) {
  try {
    whole_source_rate("log.csv", "column 'time_s'", 1e-5, 2000, true);
    FAIL() << "a rate of 1e-5 Hz was taken";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("Give the times in seconds"), std::string::npos) << e.what();
  }
  // Review 10, C3: an XML <SampleRate> of 0 has no stamps to give in seconds.
  try {
    whole_source_rate("rec.xml", "<SampleRate> at line 4", 0, 2000, false);
    FAIL() << "a rate of 0 Hz was taken";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).find("times in seconds"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("Give the rate in whole Hz, at least 2 kHz"), std::string::npos) << e.what();
  }
}

// Review 14, F4: stamps 1e12 s from an epoch keep steps of 0.12 ms only; the same stamps from the
// recording's start are exact. The first are refused saying so, the second taken.
TEST(CsvResampling, StampsTooLargeToHoldTheirStepsAreRefused) {
  std::vector<double> times;
  std::vector<std::size_t> lines;
  for (int i = 0; i < 600; ++i) {
    times.push_back(1e12 + i * 1.7e-4);
    lines.push_back(std::size_t(i) + 2);
  }
  try {
    check_stamps("accel.csv", "time", times, lines, nullptr);
    FAIL() << "stamps of 1e12 s were taken";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("accel.csv: column 'time': the time stamps reach 1e+12 s"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("subtract the first stamp"), std::string::npos) << e.what();
  }
  for (std::size_t i = 0; i < times.size(); ++i) times[i] = double(i) * 1.7e-4;
  EXPECT_NEAR(check_stamps("accel.csv", "time", times, lines, nullptr), 1 / 1.7e-4, 1e-6);
}

TEST(CsvResampling, AnXmlRecordingAt5kHzIsResampled) {
  test::SampleRecordingSpec spec;
  spec.seconds = 0.5;
  spec.sample_rate_hz = 5000;
  test::TempDir dir;
  std::string xml = test::sample_recording_xml(spec);
  test::write_text_file(dir.file("canvas.xml"), xml);
  const Recording r = read_hatt_recording_xml(dir.file("canvas.xml"), default_field_map());
  EXPECT_EQ(r.sample_rate_hz, 10000.0);
  EXPECT_EQ(r.samples(), 5000u);
  EXPECT_NE(r.source_texts.at("resampled").find("from 5000 Hz"), std::string::npos);
}

}  // namespace
}  // namespace haptex::convert
