#pragma once
// The model's samples (docs/predict.md, "The model's sample"): a window starting at sample t has as
// target the amplitude spectrum (bins 1..100) of the 1000 acceleration samples [t, t + 1000), and as
// action the 10 low-passed normal-force and 10 low-passed speed samples ending at its middle, t + 500.
// The action describes the vibration around it: strokes change speed by half within 100 ms, so the
// 1 ms before a window says little about its end. A window uses samples [t, t + 1000).
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace haptex::align {

inline constexpr std::size_t kActionSamples = 10;    // 1 ms at 10 kHz
inline constexpr std::size_t kActionValues = 2 * kActionSamples;
inline constexpr std::size_t kWindowSamples = 1000;  // 100 ms
inline constexpr std::size_t kTargetBins = 100;
// The action's last sample, counted from the window's first: the window's middle.
inline constexpr std::size_t kActionEnd = kWindowSamples / 2;

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

// t = 0, stride, 2 stride, ... while t + 1000 <= samples.
std::vector<std::int64_t> window_starts(std::size_t samples, std::size_t stride);

// Every recording's windows on all cores, in the order of `recordings` then start.
WindowTable build_windows(const std::vector<RecordingSignals>& recordings, std::size_t stride);

// "/windows[w] (material, recording r, start t)": how every message names a window (split, train, qa).
std::string window_place(std::size_t w, std::string_view material, std::int64_t recording, std::int64_t start);

// The first sample a window starting at t uses, and one past its last.
inline std::int64_t window_first_sample(std::int64_t t) { return t; }
inline std::int64_t window_end_sample(std::int64_t t) { return t + std::int64_t(kWindowSamples); }
// The first of the window's action samples (the last is window_action_first(t) + 9 = t + kActionEnd).
inline std::int64_t window_action_first(std::int64_t t) { return t + std::int64_t(kActionEnd + 1 - kActionSamples); }

}  // namespace haptex::align
