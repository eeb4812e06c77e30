#include "core/signal/stft.hpp"

#include <gtest/gtest.h>

#include <complex>
#include <random>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "tests/support/npy.hpp"
#include "tests/support/random_signal.hpp"

namespace haptex::signal {
namespace {

using test::load_golden;
using test::random_signal;
using test::max_scaled_error;

std::vector<double> interleave(const std::vector<std::complex<double>>& values) {
  std::vector<double> out;
  for (const auto& v : values) {
    out.push_back(v.real());
    out.push_back(v.imag());
  }
  return out;
}

TEST(SignalStft, HannMatchesScipyGetWindow) {
  for (std::size_t n : {64, 63, 1000}) {
    const auto expected = load_golden("signal/hann_" + std::to_string(n) + ".npy").data;
    EXPECT_LT(max_scaled_error(hann_periodic(n), expected), 1e-14) << n;
  }
  EXPECT_EQ(hann_periodic(1), std::vector<double>{1.0});
}

TEST(SignalStft, FrameCounts) {
  EXPECT_EQ(stft_frames(500, {64, 16, true}), 33u);   // 1 + ceil(500 / 16)
  EXPECT_EQ(stft_frames(496, {64, 16, true}), 32u);   // 1 + 496 / 16
  EXPECT_EQ(stft_frames(500, {64, 16, false}), 28u);  // 1 + (500 - 64) / 16
  EXPECT_EQ(stft_frames(63, {64, 16, false}), 0u);
}

TEST(SignalStft, ForwardMatchesNumpyFraming) {
  const auto x = load_golden("signal/stft_x.npy").data;  // 500 samples
  for (bool centered : {true, false}) {
    const auto expected = load_golden(centered ? "signal/stft_centered.npy" : "signal/stft_uncentered.npy");
    const auto S = stft(x, {64, 16, centered});
    ASSERT_EQ(S.frames, expected.rows()) << "centered " << centered;
    ASSERT_EQ(S.bins, expected.cols()) << "centered " << centered;
    EXPECT_LT(max_scaled_error(interleave(S.values), expected.data), 1e-12) << "centered " << centered;
  }
}

// The configuration the evaluation uses, on 10 s at 10 kHz.
TEST(SignalStft, RoundTripTenSeconds) {
  const auto x = random_signal(100000, 11);
  const StftConfig config{1000, 100, true};
  const auto back = istft(stft(x, config), x.size(), config);
  EXPECT_LT(max_scaled_error(back, x), 1e-10);
}

TEST(SignalStft, RoundTripOtherHops) {
  const auto x = random_signal(20000, 12);
  for (std::size_t hop : {1, 37, 250, 500}) {
    const StftConfig config{1000, hop, true};
    const auto back = istft(stft(x, config), x.size(), config);
    EXPECT_LT(max_scaled_error(back, x), 1e-10) << "hop " << hop;
  }
}

// Not centred, the frames cover [0, 1 + (n - window) / hop) * hop + window); the first sample
// only meets the window's zero at j = 0, so it cannot be recovered and is 0.
TEST(SignalStft, RoundTripNotCentred) {
  const auto x = random_signal(5000, 13);
  const StftConfig config{256, 64, false};
  const auto back = istft(stft(x, config), x.size(), config);
  const std::size_t covered = (stft_frames(x.size(), config) - 1) * 64 + 256;  // 4992
  EXPECT_EQ(back[0], 0.0);
  EXPECT_LT(max_scaled_error(std::vector<double>(back.begin() + 1, back.begin() + covered),
                             std::vector<double>(x.begin() + 1, x.begin() + covered)),
            1e-10);
  for (std::size_t i = covered; i < x.size(); ++i) EXPECT_EQ(back[i], 0.0) << i;
}

// The inverse is a least-squares fit: a modified spectrogram comes back as the signal whose
// STFT is closest, e.g. a scaled spectrogram gives the scaled signal.
TEST(SignalStft, InverseIsLinear) {
  const auto x = random_signal(3000, 14);
  const StftConfig config{128, 32, true};
  auto S = stft(x, config);
  for (auto& v : S.values) v *= 2.5;
  const auto back = istft(S, x.size(), config);
  std::vector<double> scaled(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) scaled[i] = 2.5 * x[i];
  EXPECT_LT(max_scaled_error(back, scaled), 1e-12);
}

TEST(SignalStft, RejectsBadConfigurations) {
  const std::vector<double> x(100, 1.0);
  EXPECT_THROW(stft(x, {0, 10, true}), Error);
  EXPECT_THROW(stft(x, {64, 0, true}), Error);
  const auto S = stft(x, {64, 16, true});
  EXPECT_THROW(istft(S, x.size(), {128, 16, true}), Error);  // bins do not fit the window
}

}  // namespace
}  // namespace haptex::signal
