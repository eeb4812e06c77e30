#include "core/ar/expected_spectrum.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/ar/ar_filter.hpp"
#include "core/ar/lsf.hpp"
#include "core/ar/texture_renderer.hpp"
#include "core/error.hpp"
#include "core/signal/spectrum.hpp"
#include "tests/support/ar_fixture.hpp"
#include "tests/support/npy.hpp"

namespace haptex::ar {
namespace {

struct GoldenCase {
  std::vector<double> a;
  double variance;
};

GoldenCase golden_model(int order) {
  char name[64];
  std::snprintf(name, sizeof name, "ar/expected_model_order%02d.npy", order);
  auto model = test::load_golden(name).data;
  GoldenCase c{std::vector<double>(model.begin(), model.end() - 1), model.back()};
  return c;
}

std::vector<double> golden(const char* what, int order) {
  char name[64];
  std::snprintf(name, sizeof name, "ar/expected_%s_order%02d.npy", what, order);
  return test::load_golden(name).data;
}

// tests/golden/expected_spectrum_golden.py: r and E|X_k|^2 from the power spectrum on a 2^20 grid,
// the amplitude as scipy's Rayleigh mean; here from the coefficients (Levinson), a different route.
TEST(ArExpectedSpectrum, AutocorrelationAndPowerMatchScipy) {
  for (int order : {2, 8, 20}) {
    SCOPED_TRACE("order " + std::to_string(order));
    const GoldenCase c = golden_model(order);
    const auto r_golden = golden("r", order), power_golden = golden("power", order);
    const auto r = ar_autocorrelation(c.a, c.variance, 1000);
    ASSERT_EQ(r.size(), r_golden.size());
    for (std::size_t m = 0; m < r.size(); ++m) ASSERT_NEAR(r[m], r_golden[m], 1e-9 * r_golden[0]) << "lag " << m;
    std::vector<double> power(100);
    windowed_power(r, power);
    for (std::size_t k = 0; k < power.size(); ++k) EXPECT_NEAR(power[k] / power_golden[k], 1.0, 1e-7) << "bin " << k + 1;
  }
}

// One AR model on every corner of a rectangle: the piecewise model that is that model everywhere.
PiecewiseArModel constant_model(const GoldenCase& c) {
  ModelSet set;
  set.max_speed = 100, set.max_force = 2;
  set.num_ar_coeff = int(c.a.size() - 1);
  set.speed_list = {0, 100, 0, 100};
  set.force_list = {0, 0, 2, 2};
  set.triangles = {{0, 1, 3}, {0, 3, 2}};
  for (int i = 0; i < 4; ++i)
    set.models.push_back({i + 1, c.a, poly_to_lsf(c.a), {1.0}, {}, c.variance, std::nullopt, set.speed_list[std::size_t(i)],
                          set.force_list[std::size_t(i)]});
  return PiecewiseArModel(set);
}

// The whole closed form, through blending and the Rayleigh amplitude, against scipy's Rayleigh mean
// of the golden power (orders 2, 8 and 20, poles up to 0.9986).
TEST(ArExpectedSpectrum, AmplitudeMatchesScipysRayleighMean) {
  for (int order : {2, 8, 20}) {
    SCOPED_TRACE("order " + std::to_string(order));
    const GoldenCase c = golden_model(order);
    const auto amplitude = golden("amplitude", order);
    const std::vector<double> speed(1000, 50.0), force(1000, 1.0);
    const std::vector<std::size_t> starts{0};
    const auto spectrum = expected_window_spectra(constant_model(c), speed, force, starts).at(0);
    ASSERT_EQ(spectrum.size(), amplitude.size());
    for (std::size_t k = 0; k < spectrum.size(); ++k) EXPECT_NEAR(spectrum[k] / amplitude[k], 1.0, 1e-6) << "bin " << k + 1;
  }
}

// tests/support/ar_fixture.hpp: only the (100 mm/s, 2 N) corner is excited, with a pole at 0.99657.
PiecewiseArModel one_model() { return test::ar_fixture(); }

// At a constant action the closed form is the stationary expectation: the mean of many renderings.
TEST(ArExpectedSpectrum, ConstantActionMatchesMonteCarlo) {
  const PiecewiseArModel model = one_model();
  const std::size_t lead = 3000, n = 1000;  // 0.99657^3000: the start is forgotten
  const std::vector<double> speed(lead + n, 100.0), force(lead + n, 2.0);
  const std::vector<std::size_t> starts{lead};
  const auto expected = expected_window_spectra(model, speed, force, starts).at(0);
  ASSERT_EQ(expected.size(), 100u);
  std::vector<double> mean(100, 0.0);
  const int renders = 400;
  for (int i = 0; i < renders; ++i) {
    const auto x = render_texture(model, speed, force, 1000 + i);
    const auto s = signal::amplitude_spectrum(std::span<const double>(x).subspan(lead, n), 100);
    for (std::size_t k = 0; k < 100; ++k) mean[k] += s[k] / renders;
  }
  // One bin's amplitude is Rayleigh (CV 0.52): 400 renders give a 2.6 % standard error per bin.
  double worst = 0;
  for (std::size_t k = 0; k < 100; ++k) worst = std::max(worst, std::fabs(mean[k] / expected[k] - 1.0));
  EXPECT_LT(worst, 0.12);
  double total_e = 0, total_m = 0;
  for (std::size_t k = 0; k < 100; ++k) total_e += expected[k], total_m += mean[k];
  EXPECT_NEAR(total_m / total_e, 1.0, 0.01);
}

// White sensor noise adds N sigma^2 to every bin's expected power: in amplitude^2, pi sigma^2 / N.
TEST(ArExpectedSpectrum, SensorNoiseAddsItsPowerToEveryBin) {
  const PiecewiseArModel model = one_model();
  const std::vector<double> speed(3000, 40.0), force(3000, 1.0);
  const std::vector<std::size_t> starts{0, 1000, 2000};
  ExpectedSpectrumOptions noisy;
  noisy.noise_power = 0.02 * 0.02;
  const auto clean = expected_window_spectra(model, speed, force, starts), with_noise = expected_window_spectra(model, speed, force, starts, noisy);
  ASSERT_EQ(with_noise.size(), 3u);
  const double added = M_PI * noisy.noise_power / 1000.0;
  for (std::size_t w = 0; w < 3; ++w)
    for (std::size_t k = 0; k < 100; ++k)
      EXPECT_NEAR(with_noise[w][k] * with_noise[w][k] - clean[w][k] * clean[w][k], added, 1e-9 * added) << "bin " << k + 1;
}

// The windows average the blends inside them: a window half at one action and half at another
// has the power halfway between the two constant windows'.
TEST(ArExpectedSpectrum, WindowAveragesItsBlends) {
  const PiecewiseArModel model = one_model();
  std::vector<double> speed(2000, 100.0), force(2000, 2.0);
  for (std::size_t i = 0; i < 1000; ++i) force[i] = 1.0;
  const std::vector<std::size_t> starts{0, 500, 1000};
  const auto s = expected_window_spectra(model, speed, force, starts);
  for (std::size_t k = 0; k < 100; ++k) {
    const double mid = s[1][k] * s[1][k], lo = s[0][k] * s[0][k], hi = s[2][k] * s[2][k];
    EXPECT_NEAR(mid, 0.5 * (lo + hi), 1e-9 * hi) << "bin " << k + 1;
  }
}

TEST(ArExpectedSpectrum, RefusesBadInput) {
  EXPECT_THROW(ar_autocorrelation(std::vector<double>{2.0, 0.1}, 1.0, 10), Error);
  EXPECT_THROW(ar_autocorrelation(std::vector<double>{1.0, NAN}, 1.0, 10), Error);
  EXPECT_THROW(ar_autocorrelation(std::vector<double>{1.0, -1.0}, 1.0, 10), Error);  // pole on the circle
  EXPECT_THROW(ar_autocorrelation(std::vector<double>{1.0, 0.5}, -1.0, 10), Error);
  EXPECT_EQ(ar_autocorrelation(std::vector<double>{1.0, 0.5}, 0.0, 4), std::vector<double>(4, 0.0));
  std::vector<double> out(3);
  EXPECT_THROW(windowed_power(std::vector<double>{}, out), Error);
  EXPECT_THROW(windowed_power(std::vector<double>(4, 1.0), out), Error);  // bins past N/2
  const PiecewiseArModel model = one_model();
  std::vector<double> speed(1500, 50.0), force(1500, 1.0);
  const std::vector<std::size_t> past{600};
  EXPECT_THROW(expected_window_spectra(model, speed, force, past), Error);
  const std::vector<std::size_t> ok{0};
  EXPECT_THROW(expected_window_spectra(model, speed, std::vector<double>(1499, 1.0), ok), Error);
  speed[5] = NAN;  // the first blend sample of the window at 0
  EXPECT_THROW(expected_window_spectra(model, speed, force, ok), Error);
  ExpectedSpectrumOptions bad;
  bad.bins = 600;
  speed[5] = 50.0;
  EXPECT_THROW(expected_window_spectra(model, speed, force, ok, bad), Error);
  bad = {};
  bad.noise_power = NAN;
  EXPECT_THROW(expected_window_spectra(model, speed, force, ok, bad), Error);
}

}  // namespace
}  // namespace haptex::ar
