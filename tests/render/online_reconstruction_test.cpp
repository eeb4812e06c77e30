#include "render/online_reconstruction.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <cstdlib>
#include <limits>
#include <new>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "render/spectral_convergence.hpp"
#include "tests/render/texture_signal.hpp"
#include "tests/render/window_statistics.hpp"
#include "tests/support/allocation_counter.hpp"
#include "tests/support/npy.hpp"


namespace haptex::render {
namespace {

using test::load_golden;
using test::max_scaled_error;

MagnitudeFrames golden_s(const char* name = "render/reconstruction_s.npy") {
  const auto array = load_golden(name);
  return {array.rows(), array.cols(), array.data};
}

struct Stream {
  std::vector<double> samples;
  std::vector<std::size_t> returned;  // samples returned by each push
  std::size_t flushed = 0;
};

Stream run(const MagnitudeFrames& s, const OnlineReconstructionOptions& options) {
  OnlineReconstruction online(options);
  Stream out;
  for (std::size_t m = 0; m < s.frames; ++m) {
    const auto block = online.push(s.row(m));
    out.returned.push_back(block.size());
    out.samples.insert(out.samples.end(), block.begin(), block.end());
  }
  const auto rest = online.flush();
  out.flushed = rest.size();
  out.samples.insert(out.samples.end(), rest.begin(), rest.end());
  return out;
}

OnlineReconstructionOptions options(std::size_t look_ahead, std::size_t iterations) {
  OnlineReconstructionOptions o;
  o.look_ahead = look_ahead;
  o.iterations = iterations;
  return o;
}

TEST(RenderOnlineReconstruction, MatchesNumpyRtisiLa) {
  const auto s = golden_s();
  for (const auto& [look_ahead, iterations] : {std::pair<std::size_t, std::size_t>{2, 2}, {0, 3}, {3, 1}}) {
    const std::string name = "rtisila_" + std::to_string(look_ahead) + "_" + std::to_string(iterations);
    const auto expected = load_golden("render/" + name + ".npy").data;
    const auto stream = run(s, options(look_ahead, iterations));
    ASSERT_EQ(stream.samples.size(), expected.size()) << name;
    EXPECT_LT(max_scaled_error(stream.samples, expected), 1e-9) << name;
  }
}

// Two frames with a look-ahead of three: nothing before the flush, then both frames' 1100 samples.
TEST(RenderOnlineReconstruction, StreamShorterThanLookAhead) {
  const auto s = golden_s("render/rtisila_short_s.npy");
  const auto expected = load_golden("render/rtisila_3_2_short.npy").data;
  const auto stream = run(s, options(3, 2));
  EXPECT_EQ(stream.returned, std::vector<std::size_t>(2, 0));
  EXPECT_EQ(stream.flushed, covered_samples(2));
  EXPECT_LT(max_scaled_error(stream.samples, expected), 1e-9);
}

// Frame m's samples start coming out when frame m + look_ahead arrives: the first look_ahead
// pushes return nothing, every later one a hop; the flush returns the rest of the covered signal.
TEST(RenderOnlineReconstruction, LatencyIsLookAheadTimesHop) {
  const auto s = golden_s();
  for (std::size_t look_ahead : {0, 1, 3, 5}) {
    OnlineReconstruction online(options(look_ahead, 1));
    EXPECT_EQ(online.latency_samples(), look_ahead * kReconstructionHop);
    const auto stream = run(s, options(look_ahead, 1));
    for (std::size_t m = 0; m < s.frames; ++m)
      EXPECT_EQ(stream.returned[m], m < look_ahead ? 0 : kReconstructionHop) << "look-ahead " << look_ahead << " frame " << m;
    EXPECT_EQ(stream.samples.size(), covered_samples(s.frames));
  }
}

// Where the output sits in time: with silence before sample 3000, frames 0..20 are silent and
// samples [0, 2100) lie in no other frame, so they must come out exactly zero, and the samples of
// frame 21's first hop must not. One hop of extra delay would shift the onset to 2200.
TEST(RenderOnlineReconstruction, OutputIsAlignedWithTheFrames) {
  auto x = test::texture_signal(8000, 5);
  std::fill(x.begin(), x.begin() + 3000, 0.0);
  const auto s = stft_magnitudes(x);
  const auto stream = run(s, options(3, 4));
  for (std::size_t n = 0; n < 2100; ++n) ASSERT_EQ(stream.samples[n], 0.0) << n;
  double onset = 0.0;
  for (std::size_t n = 2100; n < 2200; ++n) onset = std::max(onset, std::abs(stream.samples[n]));
  EXPECT_GT(onset, 0.0);
}

TEST(RenderOnlineReconstruction, ZeroFramesGiveSilence) {
  const MagnitudeFrames zero{25, kReconstructionBins, std::vector<double>(25 * kReconstructionBins, 0.0)};
  const auto stream = run(zero, options(3, 4));
  EXPECT_EQ(stream.samples.size(), covered_samples(25));
  for (double v : stream.samples) ASSERT_EQ(v, 0.0);
}

// On 10 s of texture with its exact magnitudes (see the evaluate bench for the figures): finite,
// and a longer look-ahead is more accurate.
TEST(RenderOnlineReconstruction, LookAheadImprovesAccuracy) {
  const auto s = stft_magnitudes(test::texture_signal(100000, 7));
  const auto short_look = run(s, options(1, 4)), long_look = run(s, options(5, 4));
  for (double v : long_look.samples) ASSERT_TRUE(std::isfinite(v));
  const double short_sc = spectral_convergence_db(short_look.samples, s);
  const double long_sc = spectral_convergence_db(long_look.samples, s);
  EXPECT_LT(long_sc, short_sc - 2.0);
  EXPECT_LT(long_sc, -15.0);
}

// flush() ends one stream and starts the next from scratch.
TEST(RenderOnlineReconstruction, FlushStartsANewStream) {
  const auto s = golden_s();
  OnlineReconstruction online(options(2, 2));
  std::vector<double> first, second;
  for (int pass = 0; pass < 2; ++pass) {
    auto& out = pass == 0 ? first : second;
    for (std::size_t m = 0; m < s.frames; ++m) {
      const auto block = online.push(s.row(m));
      out.insert(out.end(), block.begin(), block.end());
    }
    const auto rest = online.flush();
    out.insert(out.end(), rest.begin(), rest.end());
  }
  EXPECT_EQ(first, second);
  EXPECT_TRUE(online.flush().empty());
}

TEST(RenderOnlineReconstruction, PushDoesNotAllocate) {
  const auto s = golden_s();
  OnlineReconstructionOptions o = options(3, 4);
  o.scatter = true;
  OnlineReconstruction online(o);
  std::size_t returned = 0;
  {
    const test::CountAllocations counter;
    for (std::size_t m = 0; m < s.frames; ++m) returned += online.push(s.row(m)).size();
    returned += online.flush().size();
    EXPECT_EQ(counter.count(), 0u);
  }
  EXPECT_EQ(returned, covered_samples(s.frames));
  // The counter works: constructing one allocates its buffers.
  const test::CountAllocations counter;
  OnlineReconstruction another(options(3, 4));
  EXPECT_GT(counter.count(), 0u);
}

// Without scatter RTISI-LA plays one steady spectrum steadier than noise (0.39 here); with it, each window's amplitudes
// scatter around the prediction about as a noise-like recording's do (coefficient of variation
// sqrt(4/pi - 1) = 0.52 per bin), and the level stays the prediction's.
TEST(RenderOnlineReconstruction, ScatterVariesLikeARecording) {
  using namespace test_windows;
  const std::vector<double> a = texture(1.0);
  const std::size_t frames = 400;
  const MagnitudeFrames s = frames_of(a, frames);
  OnlineReconstructionOptions scattered = options(3, 4);
  scattered.scatter = true;
  scattered.seed = 5;
  const std::vector<double> signal = run(s, scattered).samples;
  const WindowStatistics steady = statistics(run(s, options(3, 4)).samples, 10, frames - 10);
  const WindowStatistics varied = statistics(signal, 10, frames - 10);
  std::printf("[ figures  ] median variation %.3f steady, %.3f with scatter; summed amplitude %.3f of the prediction\n",
              median(steady.variation), median(varied.variation), summed_ratio(varied, a));
  EXPECT_LT(median(steady.variation), 0.45);
  EXPECT_NEAR(median(varied.variation), kRayleighVariation, 0.1);
  EXPECT_NEAR(summed_ratio(varied, a), 1.0, 0.1);
  // The same seed gives the same signal, another seed another one.
  EXPECT_EQ(run(s, scattered).samples, signal);
  scattered.seed = 6;
  EXPECT_NE(run(s, scattered).samples, signal);
}

TEST(RenderOnlineReconstruction, RejectsBadFrames) {
  EXPECT_THROW(OnlineReconstruction(options(3, 0)), Error);
  OnlineReconstruction online;
  EXPECT_THROW(online.push(std::vector<double>(kReconstructionBins - 1, 1.0)), Error);
  std::vector<double> frame(kReconstructionBins, 1.0);
  frame[3] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(online.push(frame), Error);
  frame[3] = -2.0;
  EXPECT_THROW(online.push(frame), Error);
}

}  // namespace
}  // namespace haptex::render
