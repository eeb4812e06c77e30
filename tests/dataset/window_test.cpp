// The model's sample (dataset/window.hpp): where windows start, which samples they use, which
// action they take, and where split and qa place them.
#include "dataset/window.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace haptex::dataset {
namespace {

TEST(Window, StartsLeaveRoomForTheWindowWithItsActionInside) {
  EXPECT_EQ(window_starts(999, 100).size(), 0u);
  EXPECT_EQ(window_starts(1000, 100), (std::vector<std::int64_t>{0}));
  EXPECT_EQ(window_starts(1300, 100), (std::vector<std::int64_t>{0, 100, 200, 300}));
  EXPECT_EQ(window_first_sample(9), 9);
  EXPECT_EQ(window_end_sample(9), 1009);
  EXPECT_EQ(window_action_sample(9, 0), 59);  // samples 59, 109, .. 509, ending at the middle 509
  EXPECT_EQ(window_action_sample(9, kActionSamples - 1), 509);
  EXPECT_EQ(kActionEnd, kWindowSamples / 2);
}

TEST(Window, TheActionIsTheFortyFiveMillisecondsUpToItsLastSampleForceFirst) {
  std::vector<double> force(2000), speed(2000);
  for (std::size_t i = 0; i < force.size(); ++i) force[i] = double(i), speed[i] = 3000.0 + double(i);
  std::vector<float> action(kActionValues);
  action_ending_at<double>(force, speed, 700 + kActionEnd, action);
  for (std::size_t k = 0; k < kActionSamples; ++k) {
    EXPECT_EQ(action[k], float(750 + 50 * k));  // force[750], force[800], .. force[1200]
    EXPECT_EQ(action[kActionSamples + k], float(3750 + 50 * k));
    EXPECT_EQ(window_action_sample(700, k), std::int64_t(750 + 50 * k));
  }
  const ActionPoint p = action_point(action);  // the window's middle
  EXPECT_FLOAT_EQ(p.force, 1200.f);
  EXPECT_FLOAT_EQ(p.speed, 4200.f);
}

TEST(Window, BeforeTheSignalStartsItsFirstSampleStandsIn) {
  std::vector<double> force(300), speed(300);
  for (std::size_t i = 0; i < force.size(); ++i) force[i] = 1.0 + double(i), speed[i] = 100.0 + double(i);
  std::vector<float> action(kActionValues);
  action_ending_at<double>(force, speed, 120, action);  // samples -330, .., 20, 70, 120
  for (std::size_t k = 0; k < 7; ++k) EXPECT_EQ(action[k], 1.f) << k;
  EXPECT_EQ(action[7], 21.f);
  EXPECT_EQ(action[8], 71.f);
  EXPECT_EQ(action[9], 121.f);
  EXPECT_EQ(action[kActionValues - 1], 220.f);
}

TEST(Window, MessagesNameAWindowByMaterialRecordingAndStart) {
  EXPECT_EQ(window_place(3, "book", 1, 400), "/windows[3] (book, recording 1, start 400)");
}

}  // namespace
}  // namespace haptex::dataset
