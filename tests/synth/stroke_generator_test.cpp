#include "synth/stroke_generator.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace haptex::synth {
namespace {

TEST(StrokeGenerator, SameSeedSameStrokes) {
  const StrokeLimits limits{150, 3};
  const Strokes a = generate_strokes(limits, {2.0, 10000}, 7), b = generate_strokes(limits, {2.0, 10000}, 7);
  EXPECT_EQ(a.speed, b.speed);
  EXPECT_EQ(a.force, b.force);
  EXPECT_EQ(a.position_y, b.position_y);
  EXPECT_NE(generate_strokes(limits, {2.0, 10000}, 8).speed, a.speed);
}

TEST(StrokeGenerator, StaysWithinTheLimitsAndHasTheRequestedLength) {
  const StrokeLimits limits{120, 2.5};
  const Strokes s = generate_strokes(limits, {3.0, 10000}, 1);
  ASSERT_EQ(s.speed.size(), 30000u);
  EXPECT_EQ(s.force.size(), 30000u);
  EXPECT_GE(*std::min_element(s.speed.begin(), s.speed.end()), 0.0);
  EXPECT_LE(*std::max_element(s.speed.begin(), s.speed.end()), 120.0);
  EXPECT_GE(*std::min_element(s.force.begin(), s.force.end()), 0.0);
  EXPECT_LE(*std::max_element(s.force.begin(), s.force.end()), 2.5);
}

TEST(StrokeGenerator, TwoRecordingsCoverTheOperatingRange) {
  const StrokeLimits limits{220, 6.4};
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const Strokes a = generate_strokes(limits, {}, 2 * seed), b = generate_strokes(limits, {}, 2 * seed + 1);
    EXPECT_GE(operating_range_coverage({&a, &b}, limits), 0.9) << "seed " << seed;
  }
}

TEST(StrokeGenerator, StrokesTurnWithADwellAtLowSpeed) {
  const Strokes s = generate_strokes({200, 4}, {10.0, 10000}, 3);
  // Turns: runs of at least 20 ms below 5 mm/s; a person stroking for 10 s turns many times.
  int dwells = 0, run = 0;
  for (double v : s.speed) {
    run = v < 5 ? run + 1 : 0;
    if (run == 200) ++dwells;
  }
  EXPECT_GE(dwells, 8);
  // Motion is smooth: no jump in speed between samples beyond what a hand can do (10 m/s^2 -> 1 mm/s per 0.1 ms).
  double worst = 0;
  for (std::size_t i = 1; i < s.speed.size(); ++i) worst = std::max(worst, std::abs(s.speed[i] - s.speed[i - 1]));
  EXPECT_LT(worst, 1.0);
  double force_step = 0;  // a hand's force changes smoothly too, across strokes included
  for (std::size_t i = 1; i < s.force.size(); ++i) force_step = std::max(force_step, std::abs(s.force[i] - s.force[i - 1]));
  EXPECT_LT(force_step, 0.01);
}

TEST(StrokeGenerator, PositionFollowsTheSpeed) {
  const Strokes s = generate_strokes({100, 2}, {1.0, 10000}, 4);
  for (std::size_t i = 1000; i < s.speed.size(); i += 997) {
    const double moved = std::hypot(s.position_x[i] - s.position_x[i - 1], s.position_y[i] - s.position_y[i - 1]);
    EXPECT_NEAR(moved * 10000, s.speed[i], 1e-6 + 1e-6 * s.speed[i]);
  }
}

}  // namespace
}  // namespace haptex::synth
