#include "core/signal/sosfilt.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "tests/support/npy.hpp"

namespace haptex::signal {
namespace {

using test::load_golden;
using test::max_scaled_error;

Sos sos_from(const test::NpyArray& array) {
  Sos sos(array.rows());
  for (std::size_t r = 0; r < sos.size(); ++r)
    for (std::size_t c = 0; c < 6; ++c) sos[r][c] = array.at(r, c);
  return sos;
}

std::vector<double> row(const test::NpyArray& array, std::size_t r) {
  const auto first = array.data.begin() + static_cast<std::ptrdiff_t>(r * array.cols());
  return std::vector<double>(first, first + static_cast<std::ptrdiff_t>(array.cols()));
}

std::string name(const char* what, int order, const char* tag) {
  return std::string("signal/") + what + "_" + std::to_string(order) + "_" + tag + ".npy";
}

struct Case {
  const char* tag;
  double wn;
};
constexpr Case kCases[] = {{"0p004", 0.004}, {"0p35", 0.35}};

// Given scipy's own coefficients, so only sosfilt_zi is under test.
TEST(SignalSosfilt, ZiMatchesScipy) {
  for (const auto& c : kCases) {
    for (int order = 1; order <= 8; ++order) {
      const Sos sos = sos_from(load_golden(name("butter", order, c.tag)));
      const auto expected = load_golden(name("sosfilt_zi", order, c.tag));
      std::vector<double> zi;
      for (const auto& state : sosfilt_zi(sos)) zi.insert(zi.end(), state.begin(), state.end());
      EXPECT_LT(max_scaled_error(zi, expected.data), 1e-14) << "order " << order << " wn " << c.wn;
    }
  }
}

// A constant input started in the steady state stays exactly at that constant, section by section.
TEST(SignalSosfilt, ZiIsTheStepSteadyState) {
  const Sos sos = butter_lowpass(5, 0.1);
  auto zi = sosfilt_zi(sos);
  std::vector<double> ones(50, 1.0);
  sosfilt(sos, ones, zi);
  for (double v : ones) EXPECT_NEAR(v, 1.0, 1e-12);
}

TEST(SignalSosfilt, ForwardPassMatchesScipy) {
  const auto x = load_golden("signal/filt_x.npy").data;
  const Sos sos = sos_from(load_golden("signal/butter_4_0p35.npy"));
  auto zi = sosfilt_zi(sos);
  for (auto& state : zi)
    for (double& v : state) v *= x[0];
  std::vector<double> y = x;
  sosfilt(sos, y, zi);
  EXPECT_LT(max_scaled_error(y, load_golden("signal/sosfilt_4_0p35.npy").data), 1e-12);
}

// The state sosfilt leaves is scipy's (transposed direct form II), whatever form it filters in: a
// signal filtered in pieces, each starting from the state the last left, equals it filtered whole.
// Pieces of 1 and 2 samples too, which never reach the direct form; odd and even section counts.
TEST(SignalSosfilt, FilteringInPiecesEqualsFilteringWhole) {
  const auto x = load_golden("signal/filt_x.npy").data;
  for (int order : {3, 4, 5}) {
    const Sos sos = butter_lowpass(order, 0.05);
    auto state = sosfilt_zi(sos);
    std::vector<double> whole = x;
    sosfilt(sos, whole, state);
    for (std::size_t cut : {std::size_t(1), std::size_t(2), std::size_t(3), x.size() / 3}) {
      auto zi = sosfilt_zi(sos);
      std::vector<double> pieces = x;
      std::span<double> all(pieces);
      sosfilt(sos, all.subspan(0, 1), zi);
      sosfilt(sos, all.subspan(1, cut), zi);
      sosfilt(sos, all.subspan(1 + cut), zi);
      EXPECT_LT(max_scaled_error(pieces, whole), 1e-12) << "order " << order << " cut " << cut;
    }
  }
}

TEST(SignalSosfilt, FiltfiltMatchesScipyForAllOrders) {
  const auto x = load_golden("signal/filt_x.npy").data;
  for (const auto& c : kCases) {
    const auto expected = load_golden(std::string("signal/sosfiltfilt_") + c.tag + ".npy");
    for (int order = 1; order <= 8; ++order) {
      const auto y = sosfiltfilt(butter_lowpass(order, c.wn), x);
      EXPECT_LT(max_scaled_error(y, row(expected, static_cast<std::size_t>(order - 1))), 1e-9)
          << "order " << order << " wn " << c.wn;
    }
  }
}

// The design's action filter, sosfiltfilt(butter(4, 20, fs=10000, output='sos'), x), on a 10 s
// force trace: every sample within 1e-9 of scipy, relative to that sample.
TEST(SignalSosfilt, ActionFilterOnTenSecondsMatchesScipy) {
  const auto x = load_golden("signal/force_long_x.npy").data;
  const auto expected = load_golden("signal/force_long_filtered.npy").data;
  const auto y = sosfiltfilt(butter_lowpass_hz(4, 20.0, 10000.0), x);
  ASSERT_EQ(y.size(), expected.size());
  double worst = 0;
  for (std::size_t i = 0; i < y.size(); ++i) worst = std::max(worst, std::abs(y[i] - expected[i]) / std::abs(expected[i]));
  EXPECT_LT(worst, 1e-9);
}

TEST(SignalSosfilt, PadLengthFollowsScipy) {
  EXPECT_EQ(sosfiltfilt_padlen(butter_lowpass(4, 0.004)), 15u);  // 3 * (2*2 + 1)
  // Odd orders have one b2 = 0 and one a2 = 0 (the padded origin zero and pole), which shortens it.
  EXPECT_EQ(sosfiltfilt_padlen(butter_lowpass(3, 0.004)), 12u);  // 3 * (2*2 + 1 - 1)
}

TEST(SignalSosfilt, SignalMustBeLongerThanPadLength) {
  const Sos sos = butter_lowpass(4, 0.004);
  const std::size_t padlen = sosfiltfilt_padlen(sos);
  EXPECT_THROW(sosfiltfilt(sos, std::vector<double>(padlen, 1.0)), Error);
  const auto y = sosfiltfilt(sos, std::vector<double>(padlen + 1, 2.0));
  ASSERT_EQ(y.size(), padlen + 1);
  for (double v : y) EXPECT_NEAR(v, 2.0, 1e-9);  // a constant passes unchanged
}

TEST(SignalSosfilt, RejectsMalformedFilters) {
  std::vector<double> x(100, 1.0);
  auto zi = sosfilt_zi(butter_lowpass(2, 0.1));
  EXPECT_THROW(sosfilt(butter_lowpass(4, 0.1), x, zi), Error);  // one state for two sections
  Sos unnormalised = butter_lowpass(2, 0.1);
  unnormalised[0][3] = 2.0;
  EXPECT_THROW(sosfiltfilt(unnormalised, x), Error);
  EXPECT_THROW(sosfiltfilt(Sos{}, x), Error);
}

}  // namespace
}  // namespace haptex::signal
