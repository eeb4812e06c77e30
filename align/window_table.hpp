#pragma once
// The model's samples (DESIGN.md section 3): at sample t, the action is the 10 low-passed normal-force
// and 10 low-passed speed samples ending at t, the target the amplitude spectrum (bins 1..100) of the
// 1000 acceleration samples starting at t. A window uses samples [t - 9, t + 1000).
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace haptex::align {

inline constexpr std::size_t kActionSamples = 10;    // 1 ms at 10 kHz
inline constexpr std::size_t kActionValues = 2 * kActionSamples;
inline constexpr std::size_t kWindowSamples = 1000;  // 100 ms
inline constexpr std::size_t kTargetBins = 100;

// The signals of one recording the windows are cut from.
struct RecordingSignals {
  int material = 0, recording = 0;
  std::vector<float> accel, force_lp, speed_lp;
};

struct WindowTable {
  std::vector<std::int32_t> material, recording;
  std::vector<std::int64_t> start;
  std::vector<float> action;  // rows of 20: force then speed
  std::vector<float> target;  // rows of 100
  std::size_t size() const { return start.size(); }
};

// t = 9, 9 + stride, ... while t + 1000 <= samples.
std::vector<std::int64_t> window_starts(std::size_t samples, std::size_t stride);

// Every recording's windows on all cores, in the order of `recordings` then start.
WindowTable build_windows(const std::vector<RecordingSignals>& recordings, std::size_t stride);

// "/windows[w] (material, recording r, start t)": how every message names a window (split, train, qa).
std::string window_place(std::size_t w, std::string_view material, std::int64_t recording, std::int64_t start);

// The first sample a window starting at t uses, and one past its last.
inline std::int64_t window_first_sample(std::int64_t t) { return t - std::int64_t(kActionSamples) + 1; }
inline std::int64_t window_end_sample(std::int64_t t) { return t + std::int64_t(kWindowSamples); }

}  // namespace haptex::align
