#include "core/signal/spectrum.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <numbers>
#include <vector>

#include "core/error.hpp"
#include "tests/support/allocation_counter.hpp"
#include "tests/support/npy.hpp"

namespace haptex::signal {
namespace {

using test::load_golden;
using test::max_scaled_error;

TEST(SignalSpectrum, MatchesNumpy) {
  const auto window = load_golden("signal/spectrum_window.npy").data;
  const auto expected = load_golden("signal/spectrum_bins.npy").data;
  const auto out = amplitude_spectrum(window, 100);
  ASSERT_EQ(out.size(), 100u);
  EXPECT_LT(max_scaled_error(out, expected), 1e-12);
}

// A sine of amplitude A exactly on bin k reads A at bin k, which is index k - 1 (bins start at 1).
TEST(SignalSpectrum, PureSineReadsItsAmplitude) {
  std::vector<double> window(1000);
  for (std::size_t i = 0; i < window.size(); ++i)
    window[i] = 3.0 * std::sin(2.0 * std::numbers::pi * 7.0 * static_cast<double>(i) / 1000.0 + 0.3);
  const auto out = amplitude_spectrum(window, 100);
  EXPECT_NEAR(out[6], 3.0, 1e-12);
  for (std::size_t k = 0; k < out.size(); ++k) {
    if (k == 6) continue;
    EXPECT_NEAR(out[k], 0.0, 1e-12) << "index " << k;
  }
}

TEST(SignalSpectrum, FirstBinSelectsTheRange) {
  const auto window = load_golden("signal/spectrum_window.npy").data;
  const auto expected = load_golden("signal/spectrum_bins.npy").data;  // bins 1..100
  std::vector<double> out(10);
  amplitude_spectrum(window, out, 5);
  EXPECT_LT(max_scaled_error(out, std::vector<double>(expected.begin() + 4, expected.begin() + 14)), 1e-12);
}

TEST(SignalSpectrum, NoAllocationAfterFirstCall) {
  const auto window = load_golden("signal/spectrum_window.npy").data;
  std::vector<double> out(100);
  amplitude_spectrum(window, out, 1);  // plans the size and sizes the scratch buffer
  {
    const test::CountAllocations counter;
    for (int i = 0; i < 10; ++i) amplitude_spectrum(window, out, 1);
    EXPECT_EQ(counter.count(), 0u);
  }
  // The counter works: the vector-returning form has to allocate its result.
  const test::CountAllocations counter;
  const auto allocated = amplitude_spectrum(window, 100);
  EXPECT_GT(counter.count(), 0u);
  EXPECT_EQ(allocated, out);
}

TEST(SignalSpectrum, RejectsBadWindows) {
  std::vector<double> out(100);
  EXPECT_THROW(amplitude_spectrum(std::vector<double>(150, 1.0), out, 1), Error);  // bins 1..100 need N >= 200
  EXPECT_THROW(amplitude_spectrum(std::vector<double>{}, out, 1), Error);
  EXPECT_THROW(amplitude_spectrum(std::vector<double>(199, 1.0), 100), Error);
}

}  // namespace
}  // namespace haptex::signal
