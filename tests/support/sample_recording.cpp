#include "tests/support/sample_recording.hpp"

#include "core/gzip.hpp"
#include "tests/support/run_haptex.hpp"
#include "synth/recorded_data_xml.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <random>
#include <sstream>
#include <stdexcept>

namespace haptex::test {
namespace {

constexpr double kPi = std::numbers::pi;

}  // namespace

SampleChannels make_sample_channels(const SampleRecordingSpec& spec) {
  const std::size_t n = static_cast<std::size_t>(spec.seconds * spec.sample_rate_hz);
  const double dt = 1.0 / spec.sample_rate_hz;
  std::mt19937_64 rng(spec.seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  SampleChannels c;
  double px = 0, py = 0, heading = 0, r1 = 0, r2 = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = double(i) * dt;
    const double force = 1.6 + 0.9 * std::sin(2 * kPi * 0.37 * t + double(spec.seed)) + 0.02 * std::sin(2 * kPi * 85 * t);
    const double speed = std::max(0.0, 110 + 70 * std::sin(2 * kPi * 0.6 * t) + 1.5 * std::sin(2 * kPi * 120 * t));
    // Texture vibration: a resonance near 250 Hz excited by noise, stronger with force and speed.
    const double excitation = noise(rng) * spec.roughness * (0.2 + 0.004 * speed) * (0.5 + 0.3 * force);
    const double a = 2 * 0.97 * std::cos(2 * kPi * 250 * dt);
    const double resonance = excitation + a * r1 - 0.97 * 0.97 * r2;
    r2 = r1;
    r1 = resonance;
    const double turn = 2 * kPi * 0.2 * t;  // the vibration's direction turns slowly, so DFT321 matters
    c.accel_x.push_back(resonance * std::cos(turn) + 0.01 * noise(rng));
    c.accel_y.push_back(resonance * std::sin(turn) * 0.8 + 0.01 * noise(rng));
    c.accel_z.push_back(resonance * 0.4 + 0.01 * noise(rng));
    c.force_normal.push_back(force);
    c.force_tangential.push_back(0.3 * force + 0.01 * noise(rng));
    c.speed.push_back(speed);
    heading += 2 * kPi * 0.8 * dt;  // circular strokes
    px += speed * dt * std::cos(heading);
    py += speed * dt * std::sin(heading);
    c.position_x.push_back(px);
    c.position_y.push_back(py);
    c.position_z.push_back(-0.05 * force);
  }
  return c;
}

std::string sample_recording_xml(const SampleRecordingSpec& spec) {
  const SampleChannels c = make_sample_channels(spec);
  convert::Recording r;
  r.material = spec.material;
  r.texture = spec.texture;
  r.sample_rate_hz = spec.sample_rate_hz;
  r.units = convert::kExpectedUnits;
  r.channels = {{"accel_x", c.accel_x}, {"accel_y", c.accel_y}, {"accel_z", c.accel_z},
                {"force_normal", c.force_normal}, {"speed", c.speed}};
  if (spec.with_tangential_force) r.channels["force_tangential"] = c.force_tangential;
  if (spec.with_position) {
    r.channels["position_x"] = c.position_x;
    r.channels["position_y"] = c.position_y;
    r.channels["position_z"] = c.position_z;
  }
  return synth::recorded_data_xml(r);
}

std::string sample_recording_csv(const SampleRecordingSpec& spec) {
  const SampleChannels c = make_sample_channels(spec);
  std::ostringstream out;
  out << "time_s,accelX,accelY,accelZ,forceNormal,speed\n";
  char row[160];
  for (std::size_t i = 0; i < c.speed.size(); ++i) {
    std::snprintf(row, sizeof row, "%.6f,%.6f,%.6f,%.6f,%.6f,%.6f\n", double(i) / spec.sample_rate_hz, c.accel_x[i],
                  c.accel_y[i], c.accel_z[i], c.force_normal[i], c.speed[i]);
    out << row;
  }
  return out.str();
}

void write_text_file(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + path);
}

std::string read_recording_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (!gzip::is_gzip(bytes)) return bytes;
  const std::vector<char> text = gzip::decompress(bytes, std::uintmax_t(1) << 32, path);
  return {text.begin(), text.end()};
}

void write_recording_text(const std::string& path, const std::string& text) {
  const bool gz = path.size() > 3 && path.compare(path.size() - 3, 3, ".gz") == 0;
  write_text_file(path, gz ? gzip::compress(text, 1) : text);
}

std::string one_synth_recording(const std::string& folder) {
  const CommandResult r = run_haptex({"synth", "materials", "-n", "1", "--presses", "1", "--recordings", "1", "--seconds", "0.5", "--size",
                                      "64x48", "-o", folder});
  if (r.exit_code != 0) throw std::runtime_error("haptex synth materials failed: " + r.err);
  return std::filesystem::directory_iterator(folder + "/recordings")->path().string();
}

}  // namespace haptex::test
