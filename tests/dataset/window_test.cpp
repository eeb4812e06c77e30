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
  EXPECT_EQ(window_action_first(9), 500);  // samples 500..509, ending at the middle 509
  EXPECT_EQ(kActionEnd, kWindowSamples / 2);
}

TEST(Window, TheActionIsTheMillisecondEndingAtItsLastSampleForceFirst) {
  std::vector<double> force(2000), speed(2000);
  for (std::size_t i = 0; i < force.size(); ++i) force[i] = double(i), speed[i] = 1000.0 + double(i);
  std::vector<float> action(kActionValues);
  action_ending_at<double>(force, speed, 700 + kActionEnd, action);
  for (std::size_t k = 0; k < kActionSamples; ++k) {
    EXPECT_EQ(action[k], float(1191 + k));  // force[1191 .. 1200]
    EXPECT_EQ(action[kActionSamples + k], float(2191 + k));
  }
  EXPECT_EQ(std::size_t(window_action_first(700)), 1191u);
  const ActionPoint p = action_point(action);
  EXPECT_FLOAT_EQ(p.force, 1195.5f);
  EXPECT_FLOAT_EQ(p.speed, 2195.5f);
}

TEST(Window, MessagesNameAWindowByMaterialRecordingAndStart) {
  EXPECT_EQ(window_place(3, "book", 1, 400), "/windows[3] (book, recording 1, start 400)");
}

}  // namespace
}  // namespace haptex::dataset
