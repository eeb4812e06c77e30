#pragma once
// A small Cluster Haptic Texture Database in exactly its documented layout (docs/convert.md):
// sensor_data/{accel,force,position}/TEXTURE_DIRECTION_VELOCITY_FORCE_REPEAT.csv, with the accel and
// force stamps irregular as the database's (steps of 0.21 and 0.13 ms in turn), the position at 100 Hz.
#include <string>
#include <vector>

namespace haptex::test {

struct ClusterTakeSpec {
  int texture = 0, direction_deg = 0, velocity_mm_s = 40, force_mn = 500, repeat = 0;
  double seconds = 1.5;
  double tone_hz = 200, tone_g = 0.3;  // on X; Z holds -1 g of gravity
  std::string name() const;            // "3_90_20_1000_1"
};

// Writes the takes under root/sensor_data/ and returns root.
std::string write_cluster_tree(const std::string& root, const std::vector<ClusterTakeSpec>& takes);

}  // namespace haptex::test
