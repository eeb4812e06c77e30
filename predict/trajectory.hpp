#pragma once
// A force/speed trajectory from a CSV file, as `haptex predict --csv` and `haptex render` read it:
// a header naming the columns force (or force_n, N) and speed (or speed_mm_s, mm/s), optionally
// time_s; one row per sample at 10 kHz.
#include <cstddef>
#include <string>
#include <vector>

namespace haptex::predict {

// The shortest trajectory render and play take: one action's 10 samples (1 ms).
inline constexpr std::size_t kMinTrajectorySamples = 10;

struct Trajectory {
  std::vector<float> force, speed;  // N, mm/s
};

// Throws haptex::Error (bad_input) naming the file and line: missing columns, non-numeric or
// non-finite values, negative force or speed, a time_s step other than 0.1 ms, no rows.
Trajectory read_trajectory(const std::string& path);

// A trajectory as read_trajectory reads it back: one row per sample under kTrajectoryCsvHeader
// (what `haptex play --record` keeps of the actions it played from).
inline constexpr const char* kTrajectoryCsvHeader = "time_s,force_n,speed_mm_s";
std::string trajectory_csv_text(const Trajectory& trajectory);
// Whether path starts with that header: a CSV haptex wrote, which --force may replace.
bool is_trajectory_csv(const std::string& path);
// Before writing a trajectory CSV to path: core's output checks, and with `overwrite` a refusal to
// replace a file that is not one haptex wrote (is_trajectory_csv). Throws haptex::Error (bad_input).
void check_trajectory_csv_output(const std::string& path, bool overwrite);

// The 20 action values (10 force, then 10 speed) ending at sample t (t >= 9).
void action_at(const Trajectory& trajectory, std::size_t t, float* out);

}  // namespace haptex::predict
