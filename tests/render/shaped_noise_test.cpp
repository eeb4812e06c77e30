#include "render/shaped_noise.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <vector>

#include "core/error.hpp"
#include "core/signal/spectrum.hpp"
#include "dataset/window.hpp"
#include "tests/render/window_statistics.hpp"
#include "tests/support/allocation_counter.hpp"

namespace haptex::render {
namespace {

using namespace test_windows;

// Each window's spectrum scatters around the prediction as a noise-like recording's does: mean
// amplitude the prediction (Rayleigh mean), coefficient of variation sqrt(4/pi - 1) = 0.52 per bin.
// 20 s of one spectrum: the mean of ~2000 overlapping windows (~200 independent) is good to ~4 %.
TEST(RenderShapedNoise, WindowsScatterAroundThePredictionLikeARecording) {
  const std::vector<double> a = texture(1.0);
  const std::size_t frames = 2000;
  const std::vector<double> x = shaped_noise(frames_of(a, frames), covered_samples(frames), {7});
  const WindowStatistics s = statistics(x, 10, frames - 10);
  double worst = 0;
  std::size_t worst_bin = 0;
  for (std::size_t k = 1; k + 1 < a.size(); ++k)  // the edge bins as summed_ratio leaves them out
    if (std::abs(s.mean[k] / a[k] - 1) > worst) worst = std::abs(s.mean[k] / a[k] - 1), worst_bin = k;
  const double variation = median(s.variation);
  std::printf("[ figures  ] summed amplitude %.4f of the prediction; worst bin %zu %.1f %% off; median variation %.3f\n",
              summed_ratio(s, a), worst_bin, 100 * worst, variation);
  EXPECT_NEAR(summed_ratio(s, a), 1.0, 0.03);
  EXPECT_LT(worst, 0.12);
  EXPECT_NEAR(variation, kRayleighVariation, 0.04);
}

// A louder second half is louder by as much, and the change is placed where the frames change.
TEST(RenderShapedNoise, FollowsTheFramesLevel) {
  const std::vector<double> quiet = texture(1.0), loud = texture(4.0);
  std::vector<double> all;
  for (std::size_t m = 0; m < 600; ++m) all.insert(all.end(), (m < 300 ? quiet : loud).begin(), (m < 300 ? quiet : loud).end());
  const std::vector<double> x = shaped_noise(target_magnitudes(all), covered_samples(600), {3});
  const WindowStatistics before = statistics(x, 10, 280), after = statistics(x, 310, 590);
  double ratio = 0;
  for (std::size_t k = 1; k < quiet.size(); ++k) ratio += after.mean[k] / before.mean[k] / double(quiet.size() - 1);
  EXPECT_NEAR(ratio, 4.0, 0.2);
}

TEST(RenderShapedNoise, StreamsWithoutLatencyOrAllocation) {
  const MagnitudeFrames s = frames_of(texture(1.0), 50);
  ShapedNoise noise({11});
  std::vector<double> streamed;
  streamed.reserve(covered_samples(s.frames));
  {
    const test::CountAllocations counter;
    for (std::size_t m = 0; m < s.frames; ++m) {
      const auto block = noise.push(s.row(m));
      ASSERT_EQ(block.size(), 100u);  // frame m completes samples [100 m, 100 m + 100) at once
      streamed.insert(streamed.end(), block.begin(), block.end());
    }
    const auto tail = noise.flush();
    EXPECT_EQ(tail.size(), 900u);
    streamed.insert(streamed.end(), tail.begin(), tail.end());
    EXPECT_EQ(counter.count(), 0u);
  }
  EXPECT_TRUE(noise.flush().empty());
  const std::vector<double> whole = shaped_noise(s, covered_samples(s.frames), {11});
  for (std::size_t n = 0; n < streamed.size(); ++n) ASSERT_EQ(streamed[n], whole[n]) << n;
  EXPECT_NE(shaped_noise(s, 5000, {12}), shaped_noise(s, 5000, {11}));
  EXPECT_EQ(shaped_noise(s, 5000, {11}), shaped_noise(s, 5000, {11}));
  EXPECT_EQ(shaped_noise(s, 10000, {11}).size(), 10000u);
}

TEST(RenderShapedNoise, SilentFramesGiveSilenceAndBadFramesAreRefused) {
  for (double v : shaped_noise(frames_of(std::vector<double>(dataset::kTargetBins, 0.0), 20), 2900)) ASSERT_EQ(v, 0.0);
  ShapedNoise noise;
  EXPECT_THROW(noise.push(std::vector<double>(kReconstructionBins - 1, 1.0)), Error);
  std::vector<double> frame(kReconstructionBins, 1.0);
  frame[3] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(noise.push(frame), Error);
  frame[3] = -2.0;
  EXPECT_THROW(noise.push(frame), Error);
}

}  // namespace
}  // namespace haptex::render
