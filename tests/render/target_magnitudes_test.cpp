#include "render/target_magnitudes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "core/ar/gaussian_noise.hpp"
#include "core/error.hpp"
#include "dataset/window.hpp"
#include "render/spectral_convergence.hpp"
#include "tests/support/npy.hpp"

namespace haptex::render {
namespace {

using test::load_golden;
using test::max_scaled_error;

TEST(RenderTargetMagnitudes, MatchesNumpy) {
  const auto amplitudes = load_golden("render/target_amplitudes.npy");
  const auto expected = load_golden("render/target_magnitudes.npy");
  const auto out = target_magnitudes(amplitudes.data);
  ASSERT_EQ(out.frames, expected.rows());
  ASSERT_EQ(out.bins, expected.cols());
  EXPECT_LT(max_scaled_error(out.values, expected.data), 1e-14);
  // Frame by frame, as the online reconstruction converts the model's output.
  std::vector<double> frame(kReconstructionBins, -1.0);
  target_magnitude_frame(std::span(amplitudes.data).subspan(dataset::kTargetBins, dataset::kTargetBins), frame);
  EXPECT_EQ(frame, std::vector<double>(out.row(1).begin(), out.row(1).end()));
}

TEST(RenderTargetMagnitudes, FloatInputEqualsItsDoubleWidening) {
  const auto amplitudes = load_golden("render/target_amplitudes.npy").data;
  const std::vector<float> narrow(amplitudes.begin(), amplitudes.end());
  const std::vector<double> widened(narrow.begin(), narrow.end());
  EXPECT_EQ(target_magnitudes(narrow).values, target_magnitudes(widened).values);
}

TEST(RenderTargetMagnitudes, RmsGainIsTheHannWindowsRms) {
  const auto w = signal::hann_periodic(dataset::kWindowSamples);
  double sum = 0.0;
  for (double v : w) sum += v * v;
  EXPECT_NEAR(hann_rms_gain(), std::sqrt(sum / double(w.size())), 1e-15);
}

// The chosen conversion holds where it should: for white noise the converted rectangular
// amplitudes carry the same energy as the Hann STFT's own magnitudes, frame by frame on average.
// The coherent gain 0.5 would miss by a third of the energy.
TEST(RenderTargetMagnitudes, RmsGainHoldsForNoise) {
  const std::size_t n = 100000;
  ar::GaussianNoise noise(31);
  std::vector<double> x(n);
  for (double& v : x) v = noise.next();
  const auto hann = stft_magnitudes(x);
  std::vector<double> amplitudes;
  std::vector<double> window_spectrum(dataset::kTargetBins);
  for (std::size_t m = 0; m < hann.frames; ++m) {
    signal::amplitude_spectrum(std::span(x).subspan(m * kReconstructionHop, dataset::kWindowSamples), window_spectrum, 1);
    amplitudes.insert(amplitudes.end(), window_spectrum.begin(), window_spectrum.end());
  }
  const auto converted = target_magnitudes(amplitudes);
  ASSERT_EQ(converted.frames, hann.frames);
  double converted_energy = 0.0, hann_energy = 0.0;
  for (std::size_t m = 0; m < hann.frames; ++m)
    for (std::size_t k = 1; k <= dataset::kTargetBins; ++k) {
      converted_energy += converted.row(m)[k] * converted.row(m)[k];
      hann_energy += hann.row(m)[k] * hann.row(m)[k];
    }
  EXPECT_NEAR(converted_energy / hann_energy, 1.0, 0.03);
  const double coherent = 0.5 / hann_rms_gain();
  EXPECT_GT(std::abs(coherent * coherent * converted_energy / hann_energy - 1.0), 0.2);
}

TEST(RenderTargetMagnitudes, OnlyBinsOneToHundredAreSet) {
  const std::vector<double> amplitudes(dataset::kTargetBins, 1.0);
  const auto out = target_magnitudes(amplitudes);
  EXPECT_EQ(out.row(0)[0], 0.0);
  for (std::size_t k = 1; k <= dataset::kTargetBins; ++k) EXPECT_GT(out.row(0)[k], 0.0) << k;
  for (std::size_t k = dataset::kTargetBins + 1; k < kReconstructionBins; ++k) EXPECT_EQ(out.row(0)[k], 0.0) << k;
}

TEST(RenderTargetMagnitudes, CoveredSamplesMatchTheStftFrameCount) {
  for (std::size_t n : {1000, 1099, 1100, 100000})
    EXPECT_EQ(covered_samples(signal::stft_frames(n, kReconstructionStft)), n - (n - 1000) % 100) << n;
  EXPECT_EQ(covered_samples(0), 0u);
}

TEST(RenderTargetMagnitudes, RejectsBadInput) {
  EXPECT_THROW(target_magnitudes(std::vector<double>(150, 1.0)), Error);
  std::vector<double> amplitudes(dataset::kTargetBins, 1.0);
  amplitudes[7] = -0.5;
  EXPECT_THROW(target_magnitudes(amplitudes), Error);
  amplitudes[7] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(target_magnitudes(amplitudes), Error);
  std::vector<double> frame(kReconstructionBins - 1);
  EXPECT_THROW(target_magnitude_frame(std::vector<double>(dataset::kTargetBins, 1.0), frame), Error);
}

}  // namespace
}  // namespace haptex::render
