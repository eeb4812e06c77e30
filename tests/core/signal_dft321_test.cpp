#include "core/signal/dft321.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "tests/support/npy.hpp"
#include "tests/support/random_signal.hpp"

namespace haptex::signal {
namespace {

using test::load_golden;
using test::max_scaled_error;

struct Axes {
  std::vector<double> x, y, z;
};

Axes golden_axes(const std::string& tag) {
  const auto a = load_golden("signal/dft321_axes_" + tag + ".npy");  // 3 x N
  const auto n = static_cast<std::ptrdiff_t>(a.cols());
  const auto begin = a.data.begin();
  return {{begin, begin + n}, {begin + n, begin + 2 * n}, {begin + 2 * n, begin + 3 * n}};
}

double energy(const std::vector<double>& v) {
  double sum = 0;
  for (double s : v) sum += s * s;
  return sum;
}

// Energy of each 100 ms window of out, over the three axes' energy in the same window.
std::vector<double> window_energy_ratios(const std::vector<double>& out, const Axes& a) {
  std::vector<double> ratios;
  for (std::size_t s = 0; s + 1000 <= out.size(); s += 1000) {
    const auto part = [&](const std::vector<double>& v) { return energy({v.begin() + std::ptrdiff_t(s), v.begin() + std::ptrdiff_t(s + 1000)}); };
    ratios.push_back(part(out) / (part(a.x) + part(a.y) + part(a.z)));
  }
  return ratios;
}

Axes oriented(const std::vector<double>& source, double wx, double wy, double wz) {
  Axes a;
  for (double s : source) a.x.push_back(wx * s), a.y.push_back(wy * s), a.z.push_back(wz * s);
  return a;
}

TEST(SignalDft321, WholeRecordingMatchesNumpyEvenAndOddLengths) {
  for (const std::string tag : {"even", "odd"}) {
    const Axes a = golden_axes(tag);
    const auto expected = load_golden("signal/dft321_" + tag + ".npy").data;
    EXPECT_LT(max_scaled_error(dft321_whole_recording(a.x, a.y, a.z), expected), 1e-9) << tag;
  }
}

// tests/golden/signal_golden.py: scipy's STFT and inverse, the same per-frame reduction.
TEST(SignalDft321, FrameByFrameMatchesScipy) {
  for (const std::string tag : {"even", "odd", "turning"}) {
    const Axes a = golden_axes(tag);
    const auto expected = load_golden("signal/dft321_framewise_" + tag + ".npy").data;
    EXPECT_LT(max_scaled_error(dft321(a.x, a.y, a.z), expected), 1e-9) << tag;
  }
}

// Issue 12 section 0: a tool turning once a second keeps every 100 ms window's energy within 2 %;
// the whole-recording reduction moves energy between moments.
TEST(SignalDft321, ATurningToolKeepsEveryWindowsEnergy) {
  const Axes a = golden_axes("turning");
  for (const double r : window_energy_ratios(dft321(a.x, a.y, a.z), a)) EXPECT_NEAR(r, 1.0, 0.02);
  double worst = 0;
  for (const double r : window_energy_ratios(dft321_whole_recording(a.x, a.y, a.z), a)) worst = std::max(worst, std::abs(std::log(r)));
  EXPECT_GT(worst, std::log(1.5)) << "the turning case must tell the two reductions apart";
}

TEST(SignalDft321, AFixedOrientationGivesTheWholeRecordingResult) {
  const Axes a = oriented(test::random_signal(12345, 3), 0.3, -0.8, 0.9);
  EXPECT_LT(max_scaled_error(dft321(a.x, a.y, a.z), dft321_whole_recording(a.x, a.y, a.z)), 1e-9);
}

// Weights that sum to zero leave the plain sum of the axes no phase; the principal direction has one.
TEST(SignalDft321, AxesWhoseWeightsSumToZeroKeepTheirEnergy) {
  const Axes a = oriented(test::random_signal(20000, 4), 0.3, -0.8, 0.5);
  for (const double r : window_energy_ratios(dft321(a.x, a.y, a.z), a)) EXPECT_NEAR(r, 1.0, 0.02);
}

// Per bin |Y|^2 is the sum of the axes' |U_k|^2 (DC and Nyquist included), so by Parseval the
// whole-recording output carries the three axes' total energy exactly.
TEST(SignalDft321, WholeRecordingKeepsTotalSpectralEnergy) {
  for (const std::string tag : {"even", "odd"}) {
    const Axes a = golden_axes(tag);
    const auto out = dft321_whole_recording(a.x, a.y, a.z);
    const double total = energy(a.x) + energy(a.y) + energy(a.z);
    EXPECT_NEAR(energy(out) / total, 1.0, 1e-12) << tag;
  }
}

// With one axis only, magnitude and phase are that axis' own: the signal comes back unchanged.
TEST(SignalDft321, SingleAxisIsReturnedUnchanged) {
  const std::vector<double> x = test::random_signal(1001, 7), zero(1001, 0.0);
  std::vector<double> negated(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) negated[i] = -x[i];
  for (const auto& reduce : {dft321_whole_recording, +[](std::span<const double> a, std::span<const double> b, std::span<const double> c) {
                               return dft321(a, b, c);
                             }}) {
    EXPECT_LT(max_scaled_error(reduce(zero, x, zero), x), 1e-9);
    // A sign flip is a phase of pi, which the combined phase keeps.
    EXPECT_LT(max_scaled_error(reduce(negated, zero, zero), negated), 1e-9);
  }
}

TEST(SignalDft321, RejectsAxesOfDifferentLengths) {
  std::vector<double> a(100, 1.0), b(99, 1.0);
  EXPECT_THROW(dft321(a, a, b), Error);
  EXPECT_THROW(dft321_whole_recording(a, a, b), Error);
  EXPECT_TRUE(dft321({}, {}, {}).empty());
}

}  // namespace
}  // namespace haptex::signal
