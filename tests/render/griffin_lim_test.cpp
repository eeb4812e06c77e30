#include "render/griffin_lim.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "render/spectral_convergence.hpp"
#include "tests/render/texture_signal.hpp"
#include "tests/support/npy.hpp"

namespace haptex::render {
namespace {

using test::load_golden;
using test::max_scaled_error;

MagnitudeFrames golden_s() {
  const auto array = load_golden("render/reconstruction_s.npy");
  return {array.rows(), array.cols(), array.data};
}

// 10 s of texture and its exact magnitudes: the accuracy goal's setting.
const MagnitudeFrames& texture_magnitudes() {
  static const MagnitudeFrames s = stft_magnitudes(test::texture_signal(100000, 7));
  return s;
}

// Remembered: several tests ask for the same 100-iteration run.
double texture_sc(std::size_t iterations, double momentum, Precision precision = Precision::float32) {
  static std::map<std::tuple<std::size_t, double, Precision>, double> known;
  const auto key = std::tuple{iterations, momentum, precision};
  if (const auto found = known.find(key); found != known.end()) return found->second;
  const auto& s = texture_magnitudes();
  GriffinLimOptions options;
  options.iterations = iterations;
  options.momentum = momentum;
  options.seed = 3;
  options.precision = precision;
  return known[key] = spectral_convergence_db(griffin_lim(s, covered_samples(s.frames), options), s);
}

// From zero phase there is no random draw, so the C++ and numpy iterations can be compared step
// for step, including the edge normalisation and a cut or padded length.
TEST(RenderGriffinLim, MatchesNumpyFromZeroPhase) {
  const auto s = golden_s();
  struct Case {
    const char* golden;
    std::size_t iterations, length;
    double momentum;
  };
  for (const Case c : {Case{"fgla_0p99_5", 5, 3000, 0.99}, Case{"fgla_0_5", 5, 3000, 0.0},
                       Case{"fgla_0p99_3_short", 3, 2500, 0.99}, Case{"fgla_0p99_3_long", 3, 3400, 0.99}}) {
    const auto expected = load_golden(std::string("render/") + c.golden + ".npy").data;
    GriffinLimOptions options;
    options.iterations = c.iterations;
    options.momentum = c.momentum;
    options.initial_phase = InitialPhase::zero;
    options.precision = Precision::float64;  // the goldens are numpy's float64 iterations
    const auto x = griffin_lim(s, c.length, options);
    ASSERT_EQ(x.size(), expected.size()) << c.golden;
    EXPECT_LT(max_scaled_error(x, expected), 1e-9) << c.golden;
  }
}

TEST(RenderGriffinLim, ConvergenceImprovesWithIterations) {
  double previous = texture_sc(0, 0.99);
  for (std::size_t iterations : {8, 32, 100}) {
    const double sc = texture_sc(iterations, 0.99);
    EXPECT_LT(sc, previous - 1.0) << iterations << " iterations";
    previous = sc;
  }
}

TEST(RenderGriffinLim, MomentumBeatsPlainGriffinLim) {
  EXPECT_LT(texture_sc(100, 0.99), texture_sc(100, 0.0) - 3.0);
}

// The goal: -25 dB within 100 iterations on 10 s of texture.
TEST(RenderGriffinLim, FastGriffinLimReachesMinus25Db) { EXPECT_LT(texture_sc(100, 0.99), -25.0); }

// The default float32 arithmetic converges as far as float64 (within 0.1 dB), with and without
// momentum, after a few iterations and after many.
TEST(RenderGriffinLim, Float32ConvergesAsFarAsFloat64) {
  for (const auto& [iterations, momentum] : {std::pair<std::size_t, double>{8, 0.99}, {100, 0.99}, {100, 0.0}}) {
    const double f32 = texture_sc(iterations, momentum), f64 = texture_sc(iterations, momentum, Precision::float64);
    EXPECT_NEAR(f32, f64, 0.1) << iterations << " iterations, momentum " << momentum;
  }
}

TEST(RenderGriffinLim, ZeroMagnitudesGiveSilence) {
  const MagnitudeFrames zero{30, kReconstructionBins, std::vector<double>(30 * kReconstructionBins, 0.0)};
  for (auto phase : {InitialPhase::random, InitialPhase::zero}) {
    GriffinLimOptions options;
    options.iterations = 5;
    options.initial_phase = phase;
    const auto x = griffin_lim(zero, 4000, options);
    for (double v : x) ASSERT_EQ(v, 0.0);
  }
}

TEST(RenderGriffinLim, SameSeedSameSignal) {
  const auto s = golden_s();
  GriffinLimOptions options;
  options.iterations = 4;
  options.seed = 11;
  const auto first = griffin_lim(s, 3000, options);
  EXPECT_EQ(first, griffin_lim(s, 3000, options));
  options.seed = 12;
  EXPECT_NE(first, griffin_lim(s, 3000, options));
  for (double v : first) ASSERT_TRUE(std::isfinite(v));
}

TEST(RenderGriffinLim, RejectsBadInput) {
  const auto s = golden_s();
  GriffinLimOptions options;
  options.momentum = 1.0;
  EXPECT_THROW(griffin_lim(s, 3000, options), Error);
  options.momentum = -0.1;
  EXPECT_THROW(griffin_lim(s, 3000, options), Error);
  auto bad = s;
  bad.values[42] = -1.0;
  EXPECT_THROW(griffin_lim(bad, 3000), Error);
  bad.values[42] = std::numeric_limits<double>::infinity();
  EXPECT_THROW(griffin_lim(bad, 3000), Error);
  EXPECT_THROW(griffin_lim(MagnitudeFrames{}, 3000), Error);
  const MagnitudeFrames narrow{2, 100, std::vector<double>(200, 1.0)};
  EXPECT_THROW(griffin_lim(narrow, 3000), Error);
}

}  // namespace
}  // namespace haptex::render
