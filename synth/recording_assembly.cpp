#include "synth/recording_assembly.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "core/error.hpp"
#include "dataset/layout.hpp"
#include "synth/recorded_data_xml.hpp"

namespace haptex::synth {
namespace {

constexpr double kForceRipple = 0.01;        // N per m/s^2 of vibration reaching the load cell
constexpr double kSpeedRipple = 0.5;         // mm/s per m/s^2 of vibration seen by the position sensor

}  // namespace

convert::Recording assemble_recording(const RecordingIdentity& identity, const Strokes& strokes,
                                      std::span<const double> accel, std::uint64_t seed) {
  const std::size_t n = strokes.speed.size();
  if (accel.size() != n) throw failure("assemble_recording: vibration and strokes differ in length");
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double azimuth0 = 2 * std::numbers::pi * unit(rng), turn_hz = 0.1 + 0.2 * unit(rng);

  convert::Recording r;
  r.material = identity.material;
  r.texture = identity.texture;
  r.sample_rate_hz = kSampleRateHz;
  for (const auto& [quantity, unit_name] : convert::kExpectedUnits) r.units[quantity] = unit_name;
  auto& ch = r.channels;
  using namespace dataset::layout;
  for (const char* name : {"accel_x", "accel_y", "accel_z", kForceNormal, kForceTangential, kSpeed})
    ch[name].reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = double(i) / kSampleRateHz;
    const double azimuth = azimuth0 + 2 * std::numbers::pi * turn_hz * t;
    const double elevation = 0.6 + 0.3 * std::sin(2 * std::numbers::pi * 0.05 * t);
    ch["accel_x"].push_back(accel[i] * std::cos(elevation) * std::cos(azimuth) + kAccelNoise * noise(rng));
    ch["accel_y"].push_back(accel[i] * std::cos(elevation) * std::sin(azimuth) + kAccelNoise * noise(rng));
    ch["accel_z"].push_back(accel[i] * std::sin(elevation) + kAccelNoise * noise(rng));
    const double force = std::max(0.0, strokes.force[i] + kForceRipple * accel[i]);
    ch[kForceNormal].push_back(force);
    ch[kForceTangential].push_back(identity.friction * force);
    ch[kSpeed].push_back(std::max(0.0, strokes.speed[i] + kSpeedRipple * accel[i]));
  }
  ch["position_x"] = strokes.position_x;
  ch["position_y"] = strokes.position_y;
  ch["position_z"] = strokes.position_z;
  return r;
}

dataset::TruthRecording write_recording(const std::string& path, int index, const convert::Recording& recording, Strokes&& strokes) {
  const std::string sha = write_recorded_data_xml(path, recording);
  return {index, sha, std::move(strokes.speed), std::move(strokes.force)};
}

}  // namespace haptex::synth
