// The oracle noise floor (evaluate/floors/oracle.hpp) on recordings whose generator is known exactly.
#include "evaluate/floors/oracle.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "core/ar/expected_spectrum.hpp"
#include "core/ar/gaussian_noise.hpp"
#include "core/ar/texture_renderer.hpp"
#include "core/error.hpp"
#include "evaluate/measures/spectral_distance.hpp"
#include "tests/support/ar_fixture.hpp"

namespace haptex::evaluate {
namespace {

dataset::TruthGrid two_by_two() {
  dataset::TruthGrid g{{10, 20}, {1, 2}, std::vector<double>(4 * 100)};
  for (std::size_t s = 0; s < 2; ++s)
    for (std::size_t f = 0; f < 2; ++f)
      for (std::size_t k = 0; k < 100; ++k) g.spectra[(s * 2 + f) * 100 + k] = double(1 + s + 2 * f);
  return g;
}

TEST(TruthGridOracle, InterpolatesPowerAndFallsSilentAtRest) {
  const dataset::TruthGrid g = two_by_two();
  EXPECT_DOUBLE_EQ(grid_power_at(g, 10, 1)[0], 1.0);
  EXPECT_DOUBLE_EQ(grid_power_at(g, 20, 2)[7], 16.0);
  EXPECT_DOUBLE_EQ(grid_power_at(g, 15, 1)[3], 0.5 * (1 + 4));        // between (10, 1) and (20, 1), in power
  EXPECT_DOUBLE_EQ(grid_power_at(g, 5, 1)[0], 0.5);                   // halfway to the silent speed 0
  EXPECT_DOUBLE_EQ(grid_power_at(g, 0, 2)[0], 0.0);
  EXPECT_DOUBLE_EQ(grid_power_at(g, 10, -1)[0], 0.0);
  EXPECT_DOUBLE_EQ(grid_power_at(g, 500, 9)[0], 16.0);                // held at the grid's far corner
  std::vector<double> a{0.0, 3.0};
  add_sensor_noise(a, 0.02 * 0.02 * 3);
  EXPECT_NEAR(a[0], std::sqrt(std::numbers::pi * 0.0012 / 1000), 1e-15);
  EXPECT_NEAR(a[1], std::sqrt(9 + std::numbers::pi * 0.0012 / 1000), 1e-15);
}

// A predictor is flagged only when it is closer than the oracle by more than its sampling error.
TEST(BeatsOracle, FlagsAWrongOracleNotChance) {
  std::mt19937_64 rng(4);
  std::normal_distribution<double> n(0, 0.3);
  std::vector<double> oracle, close, better;
  for (int j = 0; j < 180; ++j) {
    oracle.push_back(1.0 + n(rng));
    close.push_back(oracle.back() + 0.02 * n(rng) - 0.001);  // a hair below on average: chance
    better.push_back(oracle.back() * 0.9);                     // 10 % closer on every window: the oracle is wrong
  }
  EXPECT_FALSE(beats_oracle(close, oracle));
  EXPECT_FALSE(beats_oracle(oracle, oracle));
  EXPECT_TRUE(beats_oracle(better, oracle));
  EXPECT_FALSE(beats_oracle({0.1}, {1.0}));  // one window: no sampling error to judge by
  EXPECT_THROW(beats_oracle({1, 2}, {1, 2, 3}), Error);
}

// A recording of the fixture model along a slow speed ramp at 2 N, with the sensor noise of three
// axes as DFT321 keeps it, cut into one test section.
struct HattCase {
  dataset::Truth truth;
  MaterialSignals signals;
  std::vector<std::vector<std::vector<double>>> recorded;
};

double slow_ramp(std::size_t i) { return 60 + 40 * double(i) / 30000.0; }

HattCase hatt_case(double (*speed_at)(std::size_t) = slow_ramp) {
  const std::size_t n = 30000, begin = 6000, length = 20000;
  std::vector<double> speed(n), force(n, 2.0);
  for (std::size_t i = 0; i < n; ++i) speed[i] = speed_at(i);
  auto accel = ar::render_texture(test::ar_fixture(), speed, force, 5);
  ar::GaussianNoise noise(6);
  for (double& v : accel) v += std::sqrt(3.0) * 0.02 * noise.next();
  HattCase c;
  c.truth.accel_noise_m_s2 = 0.02;
  c.truth.materials.push_back({"Fixture", "hatt-model", test::kArFixtureXml, "", std::nullopt, {{0, "sha-of-recording-0", speed, force}}});
  auto part = [&](const std::vector<double>& v) { return std::vector<double>(v.begin() + begin, v.begin() + begin + length); };
  c.signals = {"fixture", "Fixture", {{0, 0, "sha-of-recording-0", std::int64_t(begin), part(accel), part(force), part(speed)}}, {}};
  c.recorded.push_back(grid_spectra(c.signals.test[0].accel, section_grid(length)));
  return c;
}

TEST(HattOracle, ClosedFormAgreesWithMonteCarloAndBeatsTheModelRendered) {
  const HattCase c = hatt_case();
  const auto oracle = material_oracle(c.truth, "truth.h5", c.signals, c.recorded, 1);
  ASSERT_TRUE(oracle);
  ASSERT_TRUE(oracle->ar);
  EXPECT_EQ(oracle->method, "closed form");
  ASSERT_EQ(oracle->spectra.size(), 1u);
  EXPECT_EQ(oracle->spectra[0].size(), c.recorded[0].size());
  const ArExpectation& e = *oracle->ar;
  EXPECT_LT(e.gap, 0.02);
  EXPECT_NEAR(e.closed_form / e.monte_carlo, 1.0, 0.02);
  // A renderer pays the texture's randomness twice: its own and the recording's.
  EXPECT_GT(e.rendered / e.closed_form, 1.2);
  EXPECT_LT(e.rendered / e.closed_form, 1.6);
  EXPECT_EQ(e.rendered_spectra.size(), 1u);
  EXPECT_EQ(e.rendered_spectra[0].size(), 10u);
}

// Strokes that stop and start every 0.2 s: the filter (pole 0.99657, ~15 ms of power) still rings
// after its excitation stops and builds up after it starts, which the closed form cannot see; the
// spectra disagree and Monte Carlo is used.
TEST(HattOracle, StopAndStartFallsBackToMonteCarlo) {
  ArSection s;
  s.lead = kArLeadSamples;
  for (std::size_t i = 0; i < s.lead + 20000; ++i) {
    s.speed.push_back((i / 2000) % 2 ? 0.0 : 100.0);
    s.force.push_back(2.0);
  }
  s.grid = section_grid(20000);
  const auto x = ar::render_texture(test::ar_fixture(), s.speed, s.force, 9);
  std::vector<std::size_t> shifted;
  for (std::size_t t : s.grid) shifted.push_back(t + s.lead);
  s.recorded = grid_spectra(x, shifted);
  ArExpectationOptions o;
  o.seed = 3;
  const ArExpectation e = expected_ar_spectra(test::ar_fixture(), {s}, o);
  EXPECT_GT(e.gap, 0.02);
  EXPECT_EQ(e.method, "Monte Carlo");
  EXPECT_EQ(e.spectra.size(), 1u);
  ArExpectationOptions closed_only;
  closed_only.renders = 0;
  const ArExpectation c = expected_ar_spectra(test::ar_fixture(), {s}, closed_only);
  EXPECT_EQ(c.method, "closed form");
  EXPECT_TRUE(std::isnan(c.gap));
  EXPECT_TRUE(std::isnan(c.monte_carlo));
}

double mean_distance(const std::vector<std::vector<double>>& a, const std::vector<std::vector<double>>& b) {
  double sum = 0;
  for (std::size_t j = 0; j < a.size(); ++j) sum += spectrum_distance(a[j], b[j]);
  return sum / double(a.size());
}

// The input floor is the generating model along each window's action as recorded up to its middle and
// held there for the second half (checked against the closed form on that action); it is as close as
// the oracle on a slow ramp and farther on a stroke whose speed swings within a window.
double swinging(std::size_t i) { return 90 + 60 * std::sin(2 * std::numbers::pi * 4.0 * double(i) / 10000.0); }

TEST(HattOracle, InputFloorKnowsTheActionUpToTheMiddleAndCostsWhereTheActionMoves) {
  for (const auto speed_at : {slow_ramp, swinging}) {
    const HattCase c = hatt_case(speed_at);
    const auto oracle = material_oracle(c.truth, "truth.h5", c.signals, c.recorded, 1);
    ASSERT_TRUE(oracle);
    ASSERT_EQ(oracle->input_spectra.size(), 1u);
    const auto& input = oracle->input_spectra[0];
    ASSERT_EQ(input.size(), c.recorded[0].size());
    const std::vector<std::size_t> grid = section_grid(c.signals.test[0].accel.size());
    ar::ExpectedSpectrumOptions held;
    held.noise_power = 3 * 0.02 * 0.02;
    held.update = 100;
    for (std::size_t j : {std::size_t(0), input.size() / 2, input.size() - 1}) {
      std::vector<double> speed(1000), force(1000);  // as recorded up to the middle, then held
      for (std::size_t i = 0; i < 1000; ++i) {
        speed[i] = c.signals.test[0].speed[grid[j] + std::min<std::size_t>(i, 500)];
        force[i] = c.signals.test[0].force[grid[j] + std::min<std::size_t>(i, 500)];
      }
      const std::size_t start = 0;
      const auto expected = ar::expected_window_spectra(test::ar_fixture(), speed, force, std::span(&start, 1), held)[0];
      for (std::size_t k = 0; k < expected.size(); ++k) ASSERT_NEAR(input[j][k], expected[k], 1e-9 * expected[k]) << j << " " << k;
    }
    const double ratio = mean_distance(input, c.recorded[0]) / mean_distance(oracle->spectra[0], c.recorded[0]);
    std::printf("[ figures  ] input floor / oracle %.4f (%s)\n", ratio, speed_at == slow_ramp ? "slow ramp" : "4 Hz swing");
    if (speed_at == slow_ramp)
      EXPECT_NEAR(ratio, 1.0, 0.005);
    else
      EXPECT_GT(ratio, 1.02);
  }
}

TEST(HattOracle, KnowsOnlyTheRecordingsItGenerated) {
  HattCase c = hatt_case();
  c.signals.test[0].source_sha256 = "another recording";
  EXPECT_FALSE(material_oracle(c.truth, "truth.h5", c.signals, c.recorded, 1));
  c = hatt_case();
  c.signals.id = "other";
  EXPECT_FALSE(material_oracle(c.truth, "truth.h5", c.signals, c.recorded, 1));
  c = hatt_case();
  c.truth.materials[0].recordings[0].speed_mm_s.resize(20000);
  c.truth.materials[0].recordings[0].force_n.resize(20000);
  try {
    material_oracle(c.truth, "truth.h5", c.signals, c.recorded, 1);
    FAIL() << "a true action shorter than the recording was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::bad_input);
    EXPECT_NE(std::string(e.what()).find("truth.h5"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace haptex::evaluate
