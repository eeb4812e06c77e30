#include "core/signal/butterworth.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "tests/support/npy.hpp"

namespace haptex::signal {
namespace {

using test::load_golden;
using test::max_scaled_error;

std::vector<double> flatten(const Sos& sos) {
  std::vector<double> out;
  for (const auto& s : sos) out.insert(out.end(), s.begin(), s.end());
  return out;
}

// |H(e^{jw})| of the cascade.
double gain_at(const Sos& sos, double w) {
  const std::complex<double> z1 = std::polar(1.0, -w), z2 = z1 * z1;
  std::complex<double> h = 1.0;
  for (const auto& s : sos) h *= (s[0] + s[1] * z1 + s[2] * z2) / (s[3] + s[4] * z1 + s[5] * z2);
  return std::abs(h);
}

struct Case {
  const char* tag;
  double wn;
};
constexpr Case kCases[] = {{"0p004", 0.004}, {"0p35", 0.35}};

TEST(SignalButterworth, MatchesScipyButterSos) {
  for (const auto& c : kCases) {
    for (int order = 1; order <= 8; ++order) {
      const auto expected = load_golden("signal/butter_" + std::to_string(order) + "_" + c.tag + ".npy");
      const Sos sos = butter_lowpass(order, c.wn);
      ASSERT_EQ(sos.size(), expected.rows()) << "order " << order << " wn " << c.wn;
      EXPECT_LT(max_scaled_error(flatten(sos), expected.data), 1e-12) << "order " << order << " wn " << c.wn;
    }
  }
}

// Independent of scipy: unit DC gain, -3 dB at the cut-off, a zero at Nyquist.
TEST(SignalButterworth, HasButterworthResponse) {
  for (int order = 1; order <= 8; ++order) {
    const Sos sos = butter_lowpass(order, 0.35);
    EXPECT_NEAR(gain_at(sos, 0.0), 1.0, 1e-12);
    EXPECT_NEAR(gain_at(sos, 0.35 * std::numbers::pi), std::sqrt(0.5), 1e-12);
    EXPECT_NEAR(gain_at(sos, std::numbers::pi), 0.0, 1e-6);
  }
}

// The design's action filter: butter(4, 20, fs=10000) is butter(4, 0.004).
TEST(SignalButterworth, HertzFormMatchesNormalisedCutoff) {
  EXPECT_EQ(butter_lowpass_hz(4, 20.0, 10000.0), butter_lowpass(4, 0.004));
  const auto expected = load_golden("signal/butter_4_0p004.npy");
  EXPECT_LT(max_scaled_error(flatten(butter_lowpass_hz(4, 20.0, 10000.0)), expected.data), 1e-12);
}

TEST(SignalButterworth, RejectsBadArguments) {
  EXPECT_THROW(butter_lowpass(0, 0.1), Error);
  EXPECT_THROW(butter_lowpass(2, 0.0), Error);
  EXPECT_THROW(butter_lowpass(2, 1.0), Error);
  EXPECT_THROW(butter_lowpass(2, std::nan("")), Error);
  EXPECT_THROW(butter_lowpass_hz(2, 5000.0, 10000.0), Error);
  EXPECT_THROW(butter_lowpass_hz(2, 20.0, 0.0), Error);
}

// scipy's own zpk2sos docstring example: three poles and zeros, 'nearest' pairing puts the
// padded origin pole and zero in different sections.
TEST(SignalButterworth, ZpkToSosScipyDocExample) {
  Zpk zpk;
  zpk.zeros = {-1.0, {-0.5, -0.5}, {-0.5, 0.5}};
  zpk.poles = {0.75, {0.8, 0.1}, {0.8, -0.1}};
  zpk.gain = 1.0;
  const Sos expected = {Section{1, 1, 0.5, 1, -0.75, 0}, Section{1, 1, 0, 1, -1.6, 0.65}};
  EXPECT_LT(max_scaled_error(flatten(zpk_to_sos(zpk)), flatten(expected)), 1e-15);
}

TEST(SignalButterworth, ZpkToSosRejectsUnpairedComplexRoot) {
  Zpk zpk;
  zpk.poles = {{0.5, 0.5}, 0.2};
  EXPECT_THROW(zpk_to_sos(zpk), Error);
}

}  // namespace
}  // namespace haptex::signal
