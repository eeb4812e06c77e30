#include "core/signal/dft321.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "tests/support/npy.hpp"

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

TEST(SignalDft321, MatchesNumpyEvenAndOddLengths) {
  for (const std::string tag : {"even", "odd"}) {
    const Axes a = golden_axes(tag);
    const auto expected = load_golden("signal/dft321_" + tag + ".npy").data;
    const auto out = dft321(a.x, a.y, a.z);
    EXPECT_LT(max_scaled_error(out, expected), 1e-9) << tag;
  }
}

// Per bin |Y|^2 is the sum of the axes' |U_k|^2 (DC and Nyquist included), so by Parseval the
// output carries the three axes' total energy.
TEST(SignalDft321, KeepsTotalSpectralEnergy) {
  for (const std::string tag : {"even", "odd"}) {
    const Axes a = golden_axes(tag);
    const auto out = dft321(a.x, a.y, a.z);
    const double total = energy(a.x) + energy(a.y) + energy(a.z);
    EXPECT_NEAR(energy(out) / total, 1.0, 1e-12) << tag;
  }
}

// With one axis only, magnitude and phase are that axis' own: the signal comes back unchanged.
TEST(SignalDft321, SingleAxisIsReturnedUnchanged) {
  std::mt19937 rng(7);
  std::normal_distribution<double> noise;
  std::vector<double> x(1001), zero(1001, 0.0);
  for (double& v : x) v = noise(rng);
  EXPECT_LT(max_scaled_error(dft321(zero, x, zero), x), 1e-13);
  // A sign flip is a phase of pi, which the phase of the sum keeps.
  std::vector<double> negated(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) negated[i] = -x[i];
  EXPECT_LT(max_scaled_error(dft321(negated, zero, zero), negated), 1e-13);
}

TEST(SignalDft321, RejectsAxesOfDifferentLengths) {
  std::vector<double> a(100, 1.0), b(99, 1.0);
  EXPECT_THROW(dft321(a, a, b), Error);
  EXPECT_TRUE(dft321({}, {}, {}).empty());
}

}  // namespace
}  // namespace haptex::signal
