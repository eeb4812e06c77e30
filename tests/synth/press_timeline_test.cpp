#include "synth/press_timeline.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "core/error.hpp"

namespace haptex::synth {
namespace {

TEST(PressTimeline, HasTheShapeOfAPress) {
  for (std::uint64_t seed = 0; seed < 200; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const PressTimeline t = make_press_timeline(seed);
    ASSERT_GE(t.frames(), 31);
    ASSERT_LE(t.frames(), 41);
    ASSERT_EQ(t.exposure_gain.size(), t.depth_mm.size());
    EXPECT_EQ(t.fps, 30);
    // Quiet lead-in of at least 15 frames and a few quiet frames at the end.
    EXPECT_GE(t.contact_first, 15);
    EXPECT_LE(t.contact_last, t.frames() - 4);  // at least 3 quiet frames after
    for (int f = 0; f < t.frames(); ++f) {
      const bool in_contact = f >= t.contact_first && f <= t.contact_last;
      EXPECT_EQ(t.depth_mm[std::size_t(f)] > 0, in_contact) << "frame " << f;
    }
    // One deepest frame, rising before it and falling after it.
    for (int f = 0; f < t.frames(); ++f) {
      if (f == t.peak_frame) continue;
      EXPECT_LT(t.depth_mm[std::size_t(f)], 0.96 * t.peak_depth_mm()) << "frame " << f;
    }
    for (int f = t.contact_first; f < t.peak_frame; ++f) EXPECT_LE(t.depth_mm[std::size_t(f)], t.depth_mm[std::size_t(f + 1)]);
    for (int f = t.peak_frame; f < t.contact_last; ++f) EXPECT_GE(t.depth_mm[std::size_t(f)], t.depth_mm[std::size_t(f + 1)]);
    // A brief hold: at least three frames within 10 % of the peak.
    const auto near_peak = std::count_if(t.depth_mm.begin(), t.depth_mm.end(), [&](double d) { return d >= 0.899 * t.peak_depth_mm(); });
    EXPECT_GE(near_peak, 3);
    EXPECT_NEAR(t.peak_depth_mm(), 0.12, 0.12 * 0.15 + 1e-12);
  }
}

TEST(PressTimeline, ExposureDriftsSlowlyByUnderOneGreyLevel) {
  for (std::uint64_t seed = 0; seed < 50; ++seed) {
    const PressTimeline t = make_press_timeline(seed);
    const auto [lo, hi] = std::minmax_element(t.exposure_gain.begin(), t.exposure_gain.end());
    EXPECT_LT((*hi - *lo) * 255, 1.0);  // under one grey level even at full scale
    EXPECT_GT(*hi - *lo, 0.0);
    for (int f = 1; f < t.frames(); ++f)
      EXPECT_LT(std::abs(t.exposure_gain[std::size_t(f)] - t.exposure_gain[std::size_t(f - 1)]), 0.0003);
  }
}

TEST(PressTimeline, DeterministicForASeedAndJitteredAcrossSeeds) {
  const PressTimeline a = make_press_timeline(42), b = make_press_timeline(42);
  EXPECT_EQ(a.depth_mm, b.depth_mm);
  EXPECT_EQ(a.exposure_gain, b.exposure_gain);
  EXPECT_EQ(a.peak_frame, b.peak_frame);
  std::set<int> lengths, peaks, firsts;
  for (std::uint64_t seed = 0; seed < 50; ++seed) {
    const PressTimeline t = make_press_timeline(seed);
    lengths.insert(t.frames());
    peaks.insert(t.peak_frame);
    firsts.insert(t.contact_first);
  }
  EXPECT_GE(lengths.size(), 6u);
  EXPECT_GE(peaks.size(), 6u);
  EXPECT_EQ(firsts.size(), 3u);  // 15, 16 or 17 quiet frames
}

TEST(PressTimeline, FollowsItsOptions) {
  PressTimelineOptions options;
  options.fps = 25;
  options.lead_frames = 20;
  options.peak_depth_mm = 0.3;
  options.peak_jitter = 0;
  const PressTimeline t = make_press_timeline(3, options);
  EXPECT_EQ(t.fps, 25);
  EXPECT_GE(t.contact_first, 20);
  EXPECT_DOUBLE_EQ(t.peak_depth_mm(), 0.3);
  options.peak_depth_mm = 0;
  EXPECT_THROW(make_press_timeline(3, options), Error);
}

}  // namespace
}  // namespace haptex::synth
