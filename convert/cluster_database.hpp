#pragma once
// The Cluster Haptic Texture Database (docs/convert.md, "Cluster Haptic Texture Database"): per take,
// three CSV files of one name TEXTURE_DIRECTION_VELOCITY_FORCE_REPEAT.csv under sensor_data/:
//   accel/     time,X,Y,Z   s, g      about 6 kHz, irregular time stamps
//   force/     time,force   s, N      about 6 kHz
//   position/  time,X,Y     s, mm     100 Hz
// A take becomes one recording at 10 kHz: each file's samples interpolated onto a uniform grid at its
// nominal rate and resampled (core/signal/resample.hpp) over the span all three cover; the speed is
// the position's derivative, low-passed, checked against the file name's velocity.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "convert/input_limits.hpp"
#include "convert/recording.hpp"

namespace haptex::convert {

struct ClusterTake {
  int texture = 0, direction_deg = 0, velocity_mm_s = 0, force_mn = 0, repeat = 0;
  std::string accel, force, position;  // the three files
};

inline constexpr int kClusterAccelHz = 6000, kClusterForceHz = 6000, kClusterPositionHz = 100;
// The recordings file's `field_map` for these takes: their layout is fixed, no map names it.
inline constexpr const char* kClusterLayout = "Cluster Haptic Texture Database layout (docs/convert.md)";

// The takes under `root` (the database folder holding sensor_data/, or sensor_data itself), by
// texture, direction, velocity, force and repeat. Throws haptex::Error (bad_input) naming the file:
// no sensor_data/accel folder, a file name that is not a take's, a take missing its force or
// position file.
std::vector<ClusterTake> find_cluster_takes(const std::string& root);

// The material of a texture: the name `names` gives it, or "cluster N".
std::string cluster_material(int texture, const std::map<int, std::string>& names);

// Refuses, naming `names_file`, two textures of `takes` whose materials make one material id: a
// name given to one texture that another's default "cluster N" also makes (review 9, F3) would join
// two surfaces' takes into one material; and a names file that names none of the takes' textures (a
// file for another database: review 10, F4). Returns the textures it names that no take has.
std::vector<int> check_cluster_materials(const std::vector<ClusterTake>& takes, const std::map<int, std::string>& names,
                             const std::string& names_file);

// The take as a recording of the material `names` gives its texture ("cluster N" otherwise).
// Throws haptex::Error (bad_input) naming the file, line and column: a missing column, a bad
// number, time stamps that do not increase, a rate far from the nominal one, files that overlap
// for less than one model window, a measured speed the file name contradicts.
Recording read_cluster_take(const ClusterTake& take, const std::map<int, std::string>& names,
                            std::uintmax_t max_bytes = kDefaultMaxBytes);

}  // namespace haptex::convert
