#include <gtest/gtest.h>

#include <cmath>

#include "capture/scoring/press_segmenter.hpp"

namespace haptex::capture {
namespace {

std::vector<float> course(std::initializer_list<std::pair<int, float>> runs) {
  std::vector<float> scores;
  for (const auto& [count, value] : runs) scores.insert(scores.end(), std::size_t(count), value);
  return scores;
}

SegmenterSettings settings() { return SegmenterSettings{}; }  // trigger 0.25, release 0.125

TEST(PressSegmenter, FindsOnePressItsPeakAndItsEnd) {
  std::vector<float> s = course({{10, 0.0f}, {3, 1.0f}, {1, 4.0f}, {3, 2.0f}, {10, 0.0f}});
  const auto presses = segment_presses(s, settings());
  ASSERT_EQ(presses.size(), 1u);
  EXPECT_EQ(presses[0].first, 10);
  EXPECT_EQ(presses[0].last, 16);
  EXPECT_EQ(presses[0].peak, 13);
  EXPECT_FLOAT_EQ(presses[0].peak_score, 4.0f);
}

TEST(PressSegmenter, OneOddFrameIsNotAPress) {
  EXPECT_TRUE(segment_presses(course({{10, 0.0f}, {1, 5.0f}, {10, 0.0f}}), settings()).empty());
}

TEST(PressSegmenter, AValleyBelowATenthOfThePeakSeparatesPresses) {
  // The finger lifts most of the way (0.4 of a peak of 6) and presses again.
  const auto s = course({{5, 0.0f}, {5, 6.0f}, {2, 0.4f}, {5, 8.0f}, {5, 0.0f}});
  const auto presses = segment_presses(s, settings());
  ASSERT_EQ(presses.size(), 2u);
  EXPECT_EQ(presses[0].last, 9);
  EXPECT_EQ(presses[1].first, 12);
  EXPECT_EQ(presses[1].peak, 12);
}

TEST(PressSegmenter, TheWobbleOfALingeringTouchIsNotANewPress) {
  // After the press ends at 0.3 (a tenth of 4 is 0.4), the score wobbles around 0.3..0.5: under twice the valley.
  const auto s = course({{5, 0.0f}, {5, 4.0f}, {2, 0.3f}, {2, 0.5f}, {2, 0.3f}, {2, 0.55f}, {5, 0.0f}});
  EXPECT_EQ(segment_presses(s, settings()).size(), 1u);
}

TEST(PressSegmenter, DipsWithinAPressDoNotEndIt) {
  const auto s = course({{5, 0.0f}, {5, 8.0f}, {3, 4.0f}, {5, 9.0f}, {5, 0.0f}});
  const auto presses = segment_presses(s, settings());
  ASSERT_EQ(presses.size(), 1u);
  EXPECT_EQ(presses[0].peak, 13);
}

// One contact is one press: a grasp that squeezes, eases to a third of its excess and squeezes again
// never clearly ends (it stays above a fifth of its peak and above the release), so it is one press; a
// contact that falls to a sixth of its peak between the squeezes has clearly ended (docs/capture.md).
TEST(PressSegmenter, AGraspThatEasesAndSqueezesAgainIsOnePress) {
  EXPECT_EQ(segment_presses(course({{5, 0.0f}, {5, 6.0f}, {4, 2.0f}, {5, 6.5f}, {5, 0.0f}}), settings()).size(), 1u);
  EXPECT_EQ(segment_presses(course({{5, 0.0f}, {5, 6.0f}, {4, 1.0f}, {5, 6.5f}, {5, 0.0f}}), settings()).size(), 2u);
}

TEST(PressSegmenter, SkipsFramesWithoutAScoreAndClosesAPressAtTheEnd) {
  std::vector<float> s = course({{5, 0.0f}, {3, 2.0f}});
  s.push_back(std::nanf(""));
  s.push_back(3.0f);
  const auto presses = segment_presses(s, settings());
  ASSERT_EQ(presses.size(), 1u);
  EXPECT_EQ(presses[0].last, 9) << "open at the end: closed on the last frame";
  EXPECT_EQ(presses[0].peak, 9);
}

TEST(PressSegmenter, ReportsTheStartLive) {
  PressSegmenter segmenter(settings());
  EXPECT_FALSE(segmenter.feed(0, 0.0f));
  EXPECT_FALSE(segmenter.feed(1, 1.0f));  // first frame above: not yet confirmed
  const auto started = segmenter.feed(2, 1.5f);
  ASSERT_TRUE(started);
  EXPECT_EQ(started->kind, PressSegmenter::Event::Kind::started);
  EXPECT_EQ(started->press.first, 1);
  EXPECT_TRUE(segmenter.in_press());
  const auto ended = segmenter.feed(3, 0.0f);
  ASSERT_TRUE(ended);
  EXPECT_EQ(ended->kind, PressSegmenter::Event::Kind::ended);
  EXPECT_EQ(ended->press.last, 2);
}

}  // namespace
}  // namespace haptex::capture
