#pragma once
// The model's sample, the one home of its contract (docs/predict.md, "The model's sample"):
// a window starting at sample t has as target the amplitude spectrum 2|X_k|/N (bins 1..100,
// 10..1000 Hz, rectangular window) of the 1000 acceleration samples [t, t + 1000) at 10 kHz, and as
// action the 10 low-passed normal-force and 10 low-passed speed samples ending at its middle,
// t + 500. Strokes change speed by half within 100 ms, so the 1 ms before a window says little
// about its end; the middle describes the window best. align cuts the windows, split and qa read
// their action points, train learns them, evaluate lays its grid with the same rule, and render
// predicts each frame from its middle.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace haptex::dataset {

inline constexpr double kSampleRateHz = 10000.0;  // every signal haptex keeps
inline constexpr std::size_t kWindowSamples = 1000;  // 100 ms
inline constexpr std::size_t kTargetBins = 100;      // bins 1..100: 10..1000 Hz
inline constexpr double kBinHz = kSampleRateHz / double(kWindowSamples);  // bin k is k * 10 Hz
inline constexpr std::size_t kActionSamples = 10;    // 1 ms of force and 1 ms of speed
inline constexpr std::size_t kActionValues = 2 * kActionSamples;  // force first, then speed, the newest last
// The action's last sample, counted from the window's first: the window's middle.
inline constexpr std::size_t kActionEnd = kWindowSamples / 2;
// The evaluation's grid and the reconstruction's hop: a window every 10 ms (and align's default stride).
inline constexpr std::size_t kGridStride = 100;

// t = 0, stride, 2 stride, ... while t + 1000 <= samples.
std::vector<std::int64_t> window_starts(std::size_t samples, std::size_t stride);

// The first sample a window starting at t uses, and one past its last.
inline std::int64_t window_first_sample(std::int64_t t) { return t; }
inline std::int64_t window_end_sample(std::int64_t t) { return t + std::int64_t(kWindowSamples); }
// The first of the window's action samples (the last is window_action_first(t) + 9 = t + kActionEnd).
inline std::int64_t window_action_first(std::int64_t t) { return t + std::int64_t(kActionEnd + 1 - kActionSamples); }

// The 20 action values ending at sample `last` (>= 9) of a force and a speed signal: force[last - 9
// .. last], then speed[last - 9 .. last]. The window starting at t takes last = t + kActionEnd.
template <typename T>
void action_ending_at(std::span<const T> force, std::span<const T> speed, std::size_t last, std::span<float> out) {
  const std::size_t first = last + 1 - kActionSamples;
  for (std::size_t k = 0; k < kActionSamples; ++k) {
    out[k] = float(force[first + k]);
    out[kActionSamples + k] = float(speed[first + k]);
  }
}

// A window's force-speed point, where split's coverage and qa place it: the mean of its action samples.
struct ActionPoint {
  float force = 0, speed = 0;
};
ActionPoint action_point(std::span<const float> action);

// "/windows[w] (material, recording r, start t)": how every message names a window (split, train, qa).
std::string window_place(std::size_t w, std::string_view material, std::int64_t recording, std::int64_t start);

}  // namespace haptex::dataset
