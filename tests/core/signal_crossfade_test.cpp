// Joining stretches of vibration that were not adjacent (core/signal/crossfade.hpp): the join keeps
// the signals' power, where a linear fade would halve it at the middle, and the length is what
// the overlap leaves.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "core/signal/crossfade.hpp"

namespace haptex::signal {
namespace {

TEST(Crossfade, OverlapsTheEndsWithCosineAndSineWeights) {
  std::vector<double> out{1, 1, 1, 1};
  append_crossfaded(out, std::vector<double>{2, 2, 2, 2}, 2);
  ASSERT_EQ(out.size(), 6u);
  const double a = std::numbers::pi / 8, b = 3 * std::numbers::pi / 8;
  EXPECT_DOUBLE_EQ(out[1], 1);
  EXPECT_DOUBLE_EQ(out[2], std::cos(a) + 2 * std::sin(a));
  EXPECT_DOUBLE_EQ(out[3], std::cos(b) + 2 * std::sin(b));
  EXPECT_DOUBLE_EQ(out[4], 2);
  EXPECT_DOUBLE_EQ(out[5], 2);
}

TEST(Crossfade, AnEmptyStartTakesThePieceAndTheFadeShrinksToWhatIsThere) {
  std::vector<double> out;
  append_crossfaded(out, std::vector<double>{3, 4}, 50);
  EXPECT_EQ(out, (std::vector<double>{3, 4}));
  append_crossfaded(out, std::vector<double>{5}, 50);  // one sample overlaps, weights cos and sin of pi/4
  ASSERT_EQ(out.size(), 2u);
  EXPECT_DOUBLE_EQ(out[1], (4 + 5) / std::numbers::sqrt2);
  append_crossfaded(out, std::vector<double>{}, 50);
  EXPECT_EQ(out.size(), 2u);
}

TEST(Crossfade, KeepsThePowerOfUncorrelatedVibrationThroughTheJoin) {
  constexpr std::size_t kFade = 100, kTrials = 4000;
  std::mt19937_64 random(7);
  std::normal_distribution<double> noise;
  std::vector<double> power(kFade, 0.0);
  for (std::size_t t = 0; t < kTrials; ++t) {
    std::vector<double> out(kFade), piece(kFade);
    for (double& x : out) x = noise(random);
    for (double& x : piece) x = noise(random);
    append_crossfaded(out, piece, kFade);
    ASSERT_EQ(out.size(), kFade);
    for (std::size_t i = 0; i < kFade; ++i) power[i] += out[i] * out[i] / kTrials;
  }
  // Unit power throughout; a linear fade gives 0.5 at the middle. The mean of 4000 squares of unit
  // normals has a standard deviation of 0.022.
  for (std::size_t i = 0; i < kFade; ++i) EXPECT_NEAR(power[i], 1.0, 0.1) << "sample " << i << " of the fade";
}

}  // namespace
}  // namespace haptex::signal
