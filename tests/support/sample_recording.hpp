#pragma once
// A plausible recording in the default HaTT recorded-data XML form (docs/convert.md), for tests
// and for `make demo` until the synthetic materials exist: a circular stroke with wandering force
// and speed, vibration whose amplitude grows with both, spread over three turning axes.
#include <cstdint>
#include <string>
#include <vector>

namespace haptex::test {

struct SampleRecordingSpec {
  std::string material = "Sample Canvas";
  int texture = 7;
  double seconds = 2.0;
  double sample_rate_hz = 10000.0;
  std::uint64_t seed = 1;
  double roughness = 1.0;  // scales the vibration
  bool with_position = true;
  bool with_tangential_force = true;
};

struct SampleChannels {
  std::vector<double> accel_x, accel_y, accel_z, force_normal, force_tangential, speed, position_x, position_y,
      position_z;
};

SampleChannels make_sample_channels(const SampleRecordingSpec& spec);
std::string sample_recording_xml(const SampleRecordingSpec& spec);
std::string sample_recording_csv(const SampleRecordingSpec& spec);
void write_text_file(const std::string& path, const std::string& text);
// A recording's XML text as synth writes it (PATH.xml.gz) or any plain file, and back: compressed
// again when PATH ends in .gz.
std::string read_recording_text(const std::string& path);
void write_recording_text(const std::string& path, const std::string& text);
// `haptex synth materials` of one material (one press, one 0.5 s recording) into `folder`; the path of
// its recording's XML, for a test to edit.
std::string one_synth_recording(const std::string& folder);

}  // namespace haptex::test
