#include <gtest/gtest.h>

#include "capture/device/drop_counter.hpp"

namespace haptex::capture {
namespace {

constexpr double kPeriod = 40e6;  // 25 fps

TEST(DropCounter, SequenceGapsAreLostFrames) {
  DropCounter d(kPeriod);
  EXPECT_EQ(d.observe(0, 0), 0u);
  EXPECT_EQ(d.observe(1, 40000000), 0u);
  EXPECT_EQ(d.observe(4, 160000000), 2u);
  EXPECT_EQ(d.dropped(), 2u);
  EXPECT_EQ(d.sequence_gaps(), 2u);
  EXPECT_EQ(d.timestamp_gaps(), 0u) << "the same loss is not counted twice";
}

TEST(DropCounter, TimestampGapsCountWhenSequenceNumbersDoNot) {
  DropCounter d(kPeriod);
  d.observe(10, 0);
  EXPECT_EQ(d.observe(11, 59000000), 0u) << "1.475 periods is jitter";
  EXPECT_EQ(d.observe(12, 59000000 + 121000000), 2u) << "about 3 periods: 2 frames never sent";
  EXPECT_EQ(d.timestamp_gaps(), 2u);
}

// Issue 11 point 5: a buffer the driver returned flagged (an error buffer) used a sequence number and
// a frame period, but it is no lost frame: it is counted apart.
TEST(DropCounter, FlaggedBuffersAreNotLosses) {
  DropCounter d(kPeriod);
  d.observe(10, 0);
  EXPECT_EQ(d.observe(13, 120000000, 2), 0u) << "two error buffers filled the gap";
  EXPECT_EQ(d.observe(17, 280000000, 1), 2u) << "one error buffer, two frames lost";
  EXPECT_EQ(d.dropped(), 2u);
}

TEST(DropCounter, SurvivesTheSequenceWrapping) {
  DropCounter d(kPeriod);
  d.observe(0xfffffffeu, 0);
  EXPECT_EQ(d.observe(0xffffffffu, 40000000), 0u);
  EXPECT_EQ(d.observe(1u, 120000000), 1u);
}

}  // namespace
}  // namespace haptex::capture
