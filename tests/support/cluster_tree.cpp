#include "tests/support/cluster_tree.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>

namespace haptex::test {

std::string ClusterTakeSpec::name() const {
  return std::to_string(texture) + "_" + std::to_string(direction_deg) + "_" + std::to_string(velocity_mm_s) + "_" +
         std::to_string(force_mn) + "_" + std::to_string(repeat);
}

namespace {

void write_take(const std::filesystem::path& sensor, const ClusterTakeSpec& s) {
  // Each take its own: a sensor's noise (0.01 g, seeded by the take) on every axis.
  std::mt19937 rng(std::uint32_t(std::hash<std::string>{}(s.name())));
  std::normal_distribution<double> noise(0.0, 0.01);
  const std::string file = s.name() + ".csv";
  std::ofstream accel(sensor / "accel" / file), force(sensor / "force" / file), position(sensor / "position" / file);
  accel << "time,X,Y,Z\n";
  force << "time,force\n";
  position << "time,X,Y\n";
  char line[160];
  // The database's first stamp is about 1 ms; its steps alternate 0.21 and 0.13 ms.
  double t = 0.000999;
  for (std::size_t i = 0; t < s.seconds; ++i, t += i % 2 ? 0.21e-3 : 0.13e-3) {
    const double x = s.tone_g * std::sin(2 * M_PI * s.tone_hz * t);
    std::snprintf(line, sizeof line, "%.16g,%.6f,%.6f,%.6f\n", t, x + noise(rng),
                  0.02 * std::cos(2 * M_PI * 37 * t) + noise(rng), -1.0 + noise(rng));
    accel << line;
    std::snprintf(line, sizeof line, "%.16g,%.4f\n", t, s.force_mn * 1e-3 + 0.01 * std::sin(2 * M_PI * 3 * t));
    force << line;
  }
  const double angle = s.direction_deg * M_PI / 180;
  for (double tp = 0.0; tp < s.seconds + 0.01; tp += 0.01) {
    const double d = s.velocity_mm_s * tp;
    std::snprintf(line, sizeof line, "%.6f,%.5f,%.5f\n", tp, 50 + d * std::cos(angle), 50 + d * std::sin(angle));
    position << line;
  }
}

}  // namespace

std::string write_cluster_tree(const std::string& root, const std::vector<ClusterTakeSpec>& takes) {
  const std::filesystem::path sensor = std::filesystem::path(root) / "sensor_data";
  for (const char* folder : {"accel", "force", "position"}) std::filesystem::create_directories(sensor / folder);
  for (const auto& take : takes) write_take(sensor, take);
  return root;
}

}  // namespace haptex::test
