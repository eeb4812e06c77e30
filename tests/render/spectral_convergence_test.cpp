#include "render/spectral_convergence.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "core/error.hpp"
#include "tests/support/npy.hpp"

namespace haptex::render {
namespace {

using test::load_golden;
using test::max_scaled_error;

MagnitudeFrames golden_magnitudes(const char* name) {
  const auto array = load_golden(name);
  return {array.rows(), array.cols(), array.data};
}

TEST(RenderSpectralConvergence, StftMagnitudesMatchNumpy) {
  const auto x = load_golden("render/reconstruction_x.npy").data;
  const auto expected = golden_magnitudes("render/reconstruction_s.npy");
  const auto s = stft_magnitudes(x);
  ASSERT_EQ(s.frames, expected.frames);
  ASSERT_EQ(s.bins, expected.bins);
  EXPECT_LT(max_scaled_error(s.values, expected.values), 1e-12);
}

TEST(RenderSpectralConvergence, MatchesNumpy) {
  const auto y = load_golden("render/convergence_y.npy").data;
  const auto s = golden_magnitudes("render/reconstruction_s.npy");
  const double expected = load_golden("render/convergence_db.npy").data.at(0);
  EXPECT_NEAR(spectral_convergence_db(y, s), expected, 1e-10 * std::abs(expected));
  EXPECT_NEAR(spectral_convergence_db(stft_magnitudes(y), s), expected, 1e-10 * std::abs(expected));
}

// Only the frames s has are compared: extra samples after them do not count.
TEST(RenderSpectralConvergence, ExactSignalIsMinusInfinity) {
  const auto x = load_golden("render/reconstruction_x.npy").data;
  auto s = stft_magnitudes(x);
  EXPECT_EQ(spectral_convergence_db(x, s), -std::numeric_limits<double>::infinity());
  s.frames -= 2;
  s.values.resize(s.frames * s.bins);
  EXPECT_EQ(spectral_convergence_db(x, s), -std::numeric_limits<double>::infinity());
}

TEST(RenderSpectralConvergence, ZeroTarget) {
  MagnitudeFrames zero{2, kReconstructionBins, std::vector<double>(2 * kReconstructionBins, 0.0)};
  EXPECT_EQ(spectral_convergence_db(zero, zero), -std::numeric_limits<double>::infinity());
  auto other = zero;
  other.values[5] = 1e-3;
  EXPECT_EQ(spectral_convergence_db(other, zero), std::numeric_limits<double>::infinity());
}

TEST(RenderSpectralConvergence, RejectsMismatchedShapes) {
  const auto x = load_golden("render/reconstruction_x.npy").data;
  const auto s = stft_magnitudes(x);
  EXPECT_THROW(spectral_convergence_db(std::span(x).first(x.size() - 200), s), Error);
  auto fewer = s;
  fewer.frames -= 1;
  EXPECT_THROW(spectral_convergence_db(fewer, s), Error);
}

}  // namespace
}  // namespace haptex::render
