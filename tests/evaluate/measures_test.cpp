// The measures beside the paper's distance (evaluate/measures/log_spectral_distance.hpp) and the windows
// behind the reference predictors (evaluate/inputs/window_sets.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/error.hpp"
#include "evaluate/measures/log_spectral_distance.hpp"
#include "evaluate/inputs/window_sets.hpp"

namespace haptex::evaluate {
namespace {

TEST(LogSpectralDistance, IsTheRmsOfDecibelDifferencesAboveTheFloor) {
  const std::vector<double> floor(4, 1e-3);
  const std::vector<double> a{1.0, 0.1, 1e-6, 2.0}, b{0.1, 0.1, 1e-9, 2.0};
  // Bin 1: 20 dB; bin 2: 0; bin 3: both below the floor, 0; bin 4: 0.
  EXPECT_NEAR(log_spectral_distance(a, b, floor), std::sqrt(400.0 / 4), 1e-12);
  EXPECT_DOUBLE_EQ(log_spectral_distance(a, b, floor), log_spectral_distance(b, a, floor));
  EXPECT_EQ(log_spectral_distance(a, a, floor), 0.0);
  // A quiet material's 10 % error weighs as much as a loud one's.
  const std::vector<double> quiet{0.01, 0.01, 0.01, 0.01}, quiet_off{0.011, 0.011, 0.011, 0.011};
  const std::vector<double> loud{10, 10, 10, 10}, loud_off{11, 11, 11, 11};
  EXPECT_NEAR(log_spectral_distance(quiet, quiet_off, floor), log_spectral_distance(loud, loud_off, floor), 1e-12);
}

TEST(LogSpectralDistance, RefusesMismatchedSizesAndABadFloor) {
  const std::vector<double> a{1, 2}, b{1, 2, 3}, floor{1e-3, 1e-3}, zero{1e-3, 0.0};
  EXPECT_THROW(log_spectral_distance(a, b, floor), Error);
  EXPECT_THROW(log_spectral_distance(a, a, b), Error);
  EXPECT_THROW(log_spectral_distance(a, a, zero), Error);
  EXPECT_THROW(log_spectral_distance({}, {}, {}), Error);
}

TEST(NoiseFloor, IsTheFifthPercentilePerBinAndNeverZero) {
  std::vector<std::vector<double>> windows;
  for (int j = 0; j <= 100; ++j) windows.push_back({double(j), 0.0});
  const auto floor = noise_floor(windows);
  ASSERT_EQ(floor.size(), 2u);
  EXPECT_DOUBLE_EQ(floor[0], 5.0);  // numpy.percentile(range(101), 5)
  EXPECT_EQ(floor[1], 1e-9);
  EXPECT_THROW(noise_floor({}), Error);
}

// Rayleigh-distributed window amplitudes (as noise-like texture gives) against a copy too steady.
std::vector<std::vector<double>> rayleigh_windows(double scale, double steadiness, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n(0, 1);
  std::vector<std::vector<double>> out(400, std::vector<double>(20));
  for (auto& w : out)
    for (double& v : w) {
      const double r = scale * std::hypot(n(rng), n(rng));
      v = steadiness * scale * 1.2533 + (1 - steadiness) * r;  // 1.2533 = sqrt(pi/2): the Rayleigh mean
    }
  return out;
}

TEST(SectionRealism, SeesASignalTooSteadyButNotALevelMatch) {
  const std::vector<double> floor(20, 1e-6);
  const auto recorded = rayleigh_windows(1.0, 0.0, 1), like = rayleigh_windows(1.0, 0.0, 2), steady = rayleigh_windows(1.0, 0.8, 3);
  const SectionRealism same = section_realism(like, recorded, floor), smooth = section_realism(steady, recorded, floor);
  EXPECT_NEAR(same.spread_ratio, 1.0, 0.1);
  EXPECT_LT(same.section_lsd_db, 0.5);
  EXPECT_NEAR(smooth.spread_ratio, 0.2, 0.05);  // 80 % of the spread taken away
  const SectionRealism loud = section_realism(rayleigh_windows(2.0, 0.0, 4), recorded, floor);
  EXPECT_NEAR(loud.section_lsd_db, 20 * std::log10(2.0), 0.6);
  EXPECT_NEAR(loud.spread_ratio, 1.0, 0.1);
  EXPECT_TRUE(std::isnan(section_realism({recorded[0]}, {recorded[0]}, floor).spread_ratio));
}

TEST(NearestActionSpectra, AveragesTheWindowsClosestInStandardisedAction) {
  WindowSet training;
  for (int s = 0; s < 10; ++s)
    for (int f = 0; f < 10; ++f) {
      training.spectra.push_back({double(s), double(f)});
      training.actions.push_back({10.0 * s, 0.1 * f});  // speed and force on very different scales
    }
  const auto near = nearest_action_spectra(training, {{30.0, 0.5}, {1000.0, 0.0}}, 5);
  ASSERT_EQ(near.size(), 2u);
  // The point itself and its four neighbours at one step in speed or force.
  EXPECT_DOUBLE_EQ(near[0][0], 3.0);
  EXPECT_DOUBLE_EQ(near[0][1], 5.0);
  EXPECT_GT(near[1][0], 8.0);  // far past the range: the fastest windows
  EXPECT_THROW(nearest_action_spectra(WindowSet{}, {{0, 0}}, 3), Error);
  EXPECT_THROW(nearest_action_spectra(training, {{0, 0}}, 0), Error);
}

}  // namespace
}  // namespace haptex::evaluate
