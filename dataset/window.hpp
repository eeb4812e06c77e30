#pragma once
// The model's sample, the one home of its contract (docs/predict.md, "The model's sample"):
// a window starting at sample t has as target the amplitude spectrum 2|X_k|/N (bins 1..100,
// 10..1000 Hz, rectangular window) of the 1000 acceleration samples [t, t + 1000) at 10 kHz, and as
// action 10 low-passed normal-force and 10 low-passed speed samples 5 ms apart, the last at its
// middle, t + 500: the stroke over the 45 ms up to the middle. Strokes change speed by half within
// 100 ms, so the window's first half says where its second half goes, and a live loop knows it when
// it plays the window (half a frame late). align cuts the windows, split and qa read their action
// points, train learns them, evaluate lays its grid with the same rule, and render predicts each frame
// from its middle.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace haptex::dataset {

inline constexpr double kSampleRateHz = 10000.0;  // every signal haptex keeps
// The largest acceleration or spectrum amplitude haptex accepts from a file it did not compute itself
// (predictions, truth): beyond any texture vibration (100,000 g), and far enough below float
// overflow that the statistics stay finite.
inline constexpr double kLargestAccelerationMs2 = 1e6;
inline constexpr std::size_t kWindowSamples = 1000;  // 100 ms
inline constexpr std::size_t kTargetBins = 100;      // bins 1..100: 10..1000 Hz
inline constexpr double kBinHz = kSampleRateHz / double(kWindowSamples);  // bin k is k * 10 Hz
inline constexpr std::size_t kActionSamples = 10;    // of force and of speed
inline constexpr std::size_t kActionValues = 2 * kActionSamples;  // force first, then speed, the newest last
// The action's last sample, counted from the window's first: the window's middle.
inline constexpr std::size_t kActionEnd = kWindowSamples / 2;
// Samples between two action samples: 5 ms, so the 10 span 45 ms (the force and speed are low-passed
// at 20 Hz, docs/convert.md, so 5 ms apart they still follow every turn of the stroke).
inline constexpr std::size_t kActionStep = 50;
// The evaluation's grid and the reconstruction's hop: a window every 10 ms (and align's default stride).
inline constexpr std::size_t kGridStride = 100;

// t = 0, stride, 2 stride, ... while t + 1000 <= samples.
std::vector<std::int64_t> window_starts(std::size_t samples, std::size_t stride);

// The first sample a window starting at t uses, and one past its last.
inline std::int64_t window_first_sample(std::int64_t t) { return t; }
inline std::int64_t window_end_sample(std::int64_t t) { return t + std::int64_t(kWindowSamples); }
// The sample that action sample k (0..9, the newest last) of the window starting at t is taken at:
// t + 50, t + 100, .. t + 500.
inline std::int64_t window_action_sample(std::int64_t t, std::size_t k) {
  return t + std::int64_t(kActionEnd) - std::int64_t((kActionSamples - 1 - k) * kActionStep);
}

// The 20 action values ending at sample `last` of a force and a speed signal: force[last - 450],
// force[last - 400], .. force[last], then speed at the same samples. The window starting at t takes
// last = t + kActionEnd. Before a signal's first sample (a trajectory's first 45 ms) its first
// sample stands in: the stroke held still until it starts.
template <typename T>
void action_ending_at(std::span<const T> force, std::span<const T> speed, std::size_t last, std::span<float> out) {
  for (std::size_t k = 0; k < kActionSamples; ++k) {
    const std::size_t back = (kActionSamples - 1 - k) * kActionStep;
    const std::size_t i = last >= back ? last - back : 0;
    out[k] = float(force[i]);
    out[kActionSamples + k] = float(speed[i]);
  }
}

// A window's force-speed point, where split's coverage and qa place it: its action at the window's
// middle (the newest action sample).
struct ActionPoint {
  float force = 0, speed = 0;
};
ActionPoint action_point(std::span<const float> action);

// "/windows[w] (material, recording r, start t)": how every message names a window (split, train, qa).
std::string window_place(std::size_t w, std::string_view material, std::int64_t recording, std::int64_t start);

}  // namespace haptex::dataset
