// Resampling against scipy 1.10 (tests/golden/resample_golden.py): the Kaiser low-pass, resample_poly
// with padtype 'mean' for six ratios (one a 20-million-tap filter), and irregular time stamps through numpy.interp then 5/3.
#include "core/signal/resample.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "tests/support/npy.hpp"

namespace haptex::signal {
namespace {

using test::load_golden;
using test::max_scaled_error;

TEST(Resample, TheKaiserLowPassIsScipysFirwin) {
  EXPECT_LT(max_scaled_error(kaiser_lowpass(101, 0.2, 5.0), load_golden("resample/kaiser_101_0p2.npy").data), 1e-13);
}

TEST(Resample, ResamplePolyMatchesScipyForEveryRatio) {
  const std::vector<double> x = load_golden("resample/poly_x.npy").data;
  for (const auto& [up, down] : {std::pair{5, 3}, {3, 5}, {100, 441}, {2, 1}, {10, 6}}) {
    SCOPED_TRACE(std::to_string(up) + "/" + std::to_string(down));
    const std::vector<double> expected =
        load_golden("resample/poly_" + std::to_string(up) + "_" + std::to_string(down) + ".npy").data;
    const std::vector<double> y = resample_poly(x, up, down);
    ASSERT_EQ(y.size(), expected.size());
    EXPECT_LT(max_scaled_error(y, expected), 1e-12);
  }
  EXPECT_EQ(resample_poly(x, 4, 4), x) << "equal rates: the input";
}

// A live player's stream, in blocks of any size, gives what the whole signal gives (of mean 0, where
// padtype 'mean' changes nothing): 10 kHz to a sound card's 48 and 44.1 kHz, and a down-sampling.
TEST(Resample, AStreamInBlocksEqualsTheWholeSignal) {
  std::vector<double> x(2345);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = std::sin(0.37 * double(i)) + 0.5 * std::sin(0.05 * double(i) + 1);
  const double mean = std::accumulate(x.begin(), x.end(), 0.0) / double(x.size());
  for (double& v : x) v -= mean;
  for (const auto& [up, down] : {std::pair{48000, 10000}, {44100, 10000}, {3, 5}, {1, 1}}) {
    SCOPED_TRACE(std::to_string(up) + "/" + std::to_string(down));
    const std::vector<double> whole = resample_poly(x, up, down);
    StreamResampler stream(up, down);
    std::vector<double> streamed, block;
    for (std::size_t at = 0, size = 1; at < x.size(); at += size, size = size % 150 + 37) {
      stream.push(std::span(x).subspan(at, std::min(size, x.size() - at)), block);
      streamed.insert(streamed.end(), block.begin(), block.end());
    }
    stream.flush(block);
    streamed.insert(streamed.end(), block.begin(), block.end());
    ASSERT_EQ(streamed.size(), whole.size());
    EXPECT_LT(max_scaled_error(streamed, whole), 1e-12);
  }
}

// A source at a prime rate under the 1 MHz limit: 20 million taps, one design for every channel.
TEST(Resample, APrimeRateNearTheLimitMatchesScipy) {
  std::vector<double> x(60000);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double t = double(i) / 999983.0;
    x[i] = -0.96 + 0.3 * std::sin(2 * M_PI * 180 * t) + 0.2 * std::sin(2 * M_PI * 1300 * t + 0.3);
  }
  const std::vector<double> expected = load_golden("resample/poly_10000_999983.npy").data;
  const PolyResampler resample(10000, 999983);
  const std::vector<double> y = resample(x);
  ASSERT_EQ(y.size(), expected.size());
  EXPECT_LT(max_scaled_error(y, expected), 1e-12);
  EXPECT_EQ(resample(x), y) << "one design serves every channel";
}

TEST(Resample, IrregularStampsGoThroughInterpolationAtTheNominalRate) {
  const std::vector<double> t = load_golden("resample/irregular_t.npy").data, x = load_golden("resample/irregular_x.npy").data;
  const std::vector<double> uniform =
      interpolate_uniform(t, x, t.front(), 6000.0, std::size_t(std::floor((t.back() - t.front()) * 6000.0)) + 1);
  const std::vector<double> expected = load_golden("resample/irregular_uniform_6000.npy").data;
  ASSERT_EQ(uniform.size(), expected.size());
  EXPECT_LT(max_scaled_error(uniform, expected), 1e-13);
  const std::vector<double> at_10k = resample_poly(uniform, 10000, 6000);
  EXPECT_LT(max_scaled_error(at_10k, load_golden("resample/irregular_10000.npy").data), 1e-12);
}

// What the filter is for: a tone above the target's Nyquist (4.5 kHz at 12 kHz, resampled to 6 kHz)
// is removed, not folded onto 1.5 kHz; a tone below it passes.
TEST(Resample, AToneAboveTheNewNyquistDoesNotAlias) {
  std::vector<double> above(12000), below(12000);
  for (std::size_t i = 0; i < above.size(); ++i) {
    above[i] = std::sin(2 * M_PI * 4500.0 * double(i) / 12000.0);
    below[i] = std::sin(2 * M_PI * 1000.0 * double(i) / 12000.0);
  }
  const auto rms = [](const std::vector<double>& v) {
    double s = 0;
    for (std::size_t i = 200; i + 200 < v.size(); ++i) s += v[i] * v[i];  // away from the edges
    return std::sqrt(s / double(v.size() - 400));
  };
  EXPECT_LT(rms(resample_poly(above, 1, 2)), 0.01);
  EXPECT_NEAR(rms(resample_poly(below, 1, 2)), std::sqrt(0.5), 0.01);
}

TEST(Resample, RefusesTimesThatDoNotIncrease) {
  const std::vector<double> t = {0.0, 1e-3, 1e-3, 2e-3}, x = {1, 2, 3, 4};
  EXPECT_THROW(interpolate_uniform(t, x, 0.0, 1000.0, 3), Error);
  EXPECT_THROW(interpolate_uniform(std::vector<double>{0.0}, std::vector<double>{1.0}, 0.0, 1000.0, 1), Error);
  // Outside the stamps, numpy.interp holds the end values.
  const std::vector<double> held = interpolate_uniform(std::vector<double>{1.0, 2.0}, std::vector<double>{5.0, 7.0}, 0.0, 1.0, 4);
  EXPECT_EQ(held, (std::vector<double>{5.0, 5.0, 7.0, 7.0}));
}

}  // namespace
}  // namespace haptex::signal
