// The delivered frame rate of a take, from the driver's timestamps, and when it is worth a warning.
#include <gtest/gtest.h>

#include "capture/recording/delivered_rate.hpp"

namespace haptex::capture {
namespace {

DeliveredRate steady(double fps, int frames, std::int64_t start_ns = 5'000'000'000) {
  DeliveredRate rate;
  for (int i = 0; i < frames; ++i) rate.observe(start_ns + std::int64_t(i * 1e9 / fps));
  return rate;
}

SlowDelivery take(double delivered, double granted) { return {"/dev/video2", delivered, granted, 60.0, 1500, 0, 0}; }

TEST(DeliveredRate, ASteadySensorMeasuresItsExactRate) {
  const DeliveredRate rate = steady(25, 100);
  ASSERT_TRUE(rate.fps());
  EXPECT_NEAR(*rate.fps(), 25.0, 1e-6) << "the intervals, not the frames, over the span";
  EXPECT_NEAR(rate.span_seconds(), 99 / 25.0, 1e-9);
  EXPECT_EQ(rate.frames(), 100u);
}

TEST(DeliveredRate, LostFramesLowerTheRate) {
  DeliveredRate rate;
  for (int i = 0; i < 100; ++i)
    if (i % 4 != 3) rate.observe(std::int64_t(i) * 40'000'000);  // every 4th frame of 25 fps lost
  EXPECT_NEAR(*rate.fps(), 25.0 * 74 / 98, 1e-6);  // 75 frames, the last at frame 98
}

TEST(DeliveredRate, ATakeTooShortIsNotJudged) {
  EXPECT_FALSE(steady(25, int(kMinRateIntervals)).fps());
  EXPECT_TRUE(steady(25, int(kMinRateIntervals) + 1).fps());
  DeliveredRate frozen;  // timestamps that do not advance
  for (int i = 0; i < 50; ++i) frozen.observe(7);
  EXPECT_FALSE(frozen.fps());
}

TEST(DeliveredRate, OnlyAClearShortfallIsWarned) {
  EXPECT_EQ(slow_delivery_warning(take(25.0, 25)), "");
  EXPECT_EQ(slow_delivery_warning(take(22.6, 25)), "") << "9.6 % short: within the margin";
  const std::string w = slow_delivery_warning(take(18.75, 25));
  EXPECT_NE(w.find("/dev/video2: the sensor delivered 18.8 frames per second (1500 frames in 60.0 s"), std::string::npos) << w;
  EXPECT_NE(w.find("25 % below the 25 fps it granted"), std::string::npos) << w;
  EXPECT_NE(w.find("exposure_time_absolute below 400"), std::string::npos) << "40 ms in 100 us units: " << w;
  EXPECT_NE(slow_delivery_warning(take(22.4, 25)), "") << "10.4 % short";
}

TEST(DeliveredRate, TheWarningCountsWhatWasLost) {
  SlowDelivery t = take(20, 30);
  t.dropped_frames = 400;
  t.error_buffers = 12;
  const std::string w = slow_delivery_warning(t);
  EXPECT_NE(w.find("(400 frames lost, 12 buffers flagged as errors)"), std::string::npos) << w;
  t.error_buffers = 0;
  EXPECT_NE(slow_delivery_warning(t).find("granted (400 frames lost). "), std::string::npos) << slow_delivery_warning(t);
  EXPECT_NE(w.find("33 % below the 30 fps"), std::string::npos) << w;
}

}  // namespace
}  // namespace haptex::capture
