#include "evaluate/measures/spectral_distance.hpp"

#include <gtest/gtest.h>

#include <numeric>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "tests/support/npy.hpp"

namespace haptex::evaluate {
namespace {

using test::load_golden;
using test::max_scaled_error;

std::vector<float> as_float(const std::vector<double>& values) { return {values.begin(), values.end()}; }

TEST(EvaluateSpectralDistance, WindowsMatchNumpy) {
  for (const std::string tag : {"10000", "12345", "1000"}) {
    const auto truth = load_golden("evaluate/distance_truth_" + tag + ".npy").data;
    const auto rendered = load_golden("evaluate/distance_rendered_" + tag + ".npy").data;
    const auto expected = load_golden("evaluate/distance_windows_" + tag + ".npy").data;
    const auto distances = window_distances(rendered, truth);
    ASSERT_EQ(distances.size(), expected.size()) << tag;
    EXPECT_EQ(distance_windows(truth.size()), expected.size()) << tag;
    for (std::size_t w = 0; w < expected.size(); ++w)
      EXPECT_NEAR(distances[w], expected[w], 1e-10 * expected[w]) << tag << " window " << w;
    const double expected_mean = std::accumulate(expected.begin(), expected.end(), 0.0) / double(expected.size());
    EXPECT_NEAR(spectral_distance(rendered, truth), expected_mean, 1e-10 * expected_mean) << tag;
  }
}

TEST(EvaluateSpectralDistance, SpectraMatchNumpy) {
  const auto a = load_golden("evaluate/spectra_a.npy"), b = load_golden("evaluate/spectra_b.npy");
  const auto expected = load_golden("evaluate/spectra_distance.npy").data;
  ASSERT_EQ(a.cols(), 100u);
  std::vector<double> distances;
  for (std::size_t r = 0; r < a.rows(); ++r)
    distances.push_back(spectrum_distance(std::span(a.data).subspan(r * 100, 100), std::span(b.data).subspan(r * 100, 100)));
  EXPECT_LT(max_scaled_error(distances, expected), 1e-12);
}

// The model's float predictions against float targets: summed in double, as numpy does on the
// float32 values widened to float64.
TEST(EvaluateSpectralDistance, FloatSpectraMatchNumpy) {
  const auto a = as_float(load_golden("evaluate/spectra_a_f32.npy").data);
  const auto b = as_float(load_golden("evaluate/spectra_b_f32.npy").data);
  const auto expected = load_golden("evaluate/spectra_distance_f32.npy").data;
  std::vector<double> distances;
  for (std::size_t r = 0; r < expected.size(); ++r)
    distances.push_back(spectrum_distance(std::span(a).subspan(r * 100, 100), std::span(b).subspan(r * 100, 100)));
  EXPECT_LT(max_scaled_error(distances, expected), 1e-12);
}

TEST(EvaluateSpectralDistance, SignalAgainstItselfIsZero) {
  const auto x = load_golden("evaluate/distance_truth_12345.npy").data;
  for (double d : window_distances(x, x)) EXPECT_EQ(d, 0.0);
}

TEST(EvaluateSpectralDistance, RejectsMismatchedOrShortInput) {
  const std::vector<double> x(2000, 1.0), y(2100, 1.0), short_x(999, 1.0);
  EXPECT_THROW(window_distances(x, y), Error);
  EXPECT_THROW(window_distances(short_x, short_x), Error);
  EXPECT_THROW(spectral_distance(short_x, short_x), Error);
  const std::vector<double> a(100, 1.0), b(99, 1.0), none;
  EXPECT_THROW(spectrum_distance(a, b), Error);
  EXPECT_THROW(spectrum_distance(none, none), Error);
  const std::vector<float> fa(100, 1.0f), fb(101, 1.0f);
  EXPECT_THROW(spectrum_distance(fa, fb), Error);
}

}  // namespace
}  // namespace haptex::evaluate
