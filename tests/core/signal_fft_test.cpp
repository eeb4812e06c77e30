#include "core/signal/fft.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <complex>
#include <functional>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "core/error.hpp"
#include "tests/support/npy.hpp"

namespace haptex::signal {
namespace {

using test::load_golden;
using test::max_scaled_error;

// Interleaved (re, im), the layout NpyArray uses for complex data.
template <typename T>
std::vector<double> interleave(const std::vector<std::complex<T>>& values) {
  std::vector<double> out;
  for (const auto& v : values) {
    out.push_back(v.real());
    out.push_back(v.imag());
  }
  return out;
}

template <typename T>
std::vector<T> cast(const std::vector<double>& values) {
  return std::vector<T>(values.begin(), values.end());
}

template <typename T>
std::vector<std::complex<T>> cast(const std::vector<std::complex<double>>& values) {
  std::vector<std::complex<T>> out;
  for (const auto& v : values) out.emplace_back(static_cast<T>(v.real()), static_cast<T>(v.imag()));
  return out;
}

template <typename T>
double forward_error(const std::string& tag) {
  const auto x = cast<T>(load_golden("signal/fft_x_" + tag + ".npy").data);
  const auto expected = load_golden("signal/fft_rfft_" + tag + ".npy");
  const auto& fft = real_fft<T>(x.size());
  std::vector<std::complex<T>> X(fft.bins());
  fft.forward(x, X);
  return max_scaled_error(interleave(X), expected.data);
}

template <typename T>
double inverse_error(const std::string& tag) {
  const auto spectrum = cast<T>(load_golden("signal/fft_spectrum_" + tag + ".npy").as_complex());
  const auto expected = load_golden("signal/fft_irfft_" + tag + ".npy");
  const auto& fft = real_fft<T>(expected.data.size());
  std::vector<T> x(fft.size());
  fft.inverse(spectrum, x);
  return max_scaled_error(std::vector<double>(x.begin(), x.end()), expected.data);
}

TEST(SignalFft, ForwardMatchesNumpyRfft) {
  EXPECT_LT(forward_error<double>("even"), 1e-12);
  EXPECT_LT(forward_error<double>("odd"), 1e-12);
}

// The golden spectra have non-zero imaginary parts at DC (and Nyquist for even N), which irfft ignores.
TEST(SignalFft, InverseMatchesNumpyIrfft) {
  EXPECT_LT(inverse_error<double>("even"), 1e-12);
  EXPECT_LT(inverse_error<double>("odd"), 1e-12);
}

// Float inputs are the float64 golden inputs rounded, so the error includes that rounding.
TEST(SignalFft, FloatPrecisionMatchesNumpy) {
  EXPECT_LT(forward_error<float>("even"), 2e-6);
  EXPECT_LT(forward_error<float>("odd"), 2e-6);
  EXPECT_LT(inverse_error<float>("even"), 2e-6);
  EXPECT_LT(inverse_error<float>("odd"), 2e-6);
}

TEST(SignalFft, InverseLeavesItsInputIntact) {
  const auto spectrum = load_golden("signal/fft_spectrum_even.npy").as_complex();
  const auto copy = spectrum;
  std::vector<double> x(1000);
  real_fft<double>(1000).inverse(spectrum, x);
  EXPECT_EQ(spectrum, copy);
}

// Arrays off FFTW's 16-byte alignment (a span into a signal) take the FFTW_UNALIGNED plans, aligned
// ones the SIMD plans: both give numpy's transform, in both precisions and both directions.
template <typename T>
void expect_same_off_alignment(double tolerance) {
  const auto x = cast<T>(load_golden("signal/fft_x_even.npy").data);
  const auto& fft = real_fft<T>(x.size());
  std::vector<T> shifted(x.size() + 1);
  std::copy(x.begin(), x.end(), shifted.begin() + 1);
  std::vector<std::complex<T>> aligned(fft.bins()), unaligned(fft.bins() + 1);
  fft.forward(x, aligned);
  const std::span<const T> off(shifted.data() + 1, x.size());
  const std::span<std::complex<T>> off_spectrum(unaligned.data() + 1, fft.bins());
  fft.forward(off, off_spectrum);
  const auto expected = load_golden("signal/fft_rfft_even.npy").data;
  EXPECT_LT(max_scaled_error(interleave(aligned), expected), tolerance);
  EXPECT_LT(max_scaled_error(interleave(std::vector<std::complex<T>>(off_spectrum.begin(), off_spectrum.end())), expected),
            tolerance);
  std::vector<T> back(x.size() + 1);
  fft.inverse(off_spectrum, std::span<T>(back.data() + 1, x.size()));
  EXPECT_LT(max_scaled_error(std::vector<double>(back.begin() + 1, back.end()), std::vector<double>(x.begin(), x.end())), tolerance);
}

TEST(SignalFft, UnalignedArraysGiveTheSameTransform) {
  expect_same_off_alignment<double>(1e-12);
  expect_same_off_alignment<float>(1e-5);
}

TEST(SignalFft, SharedInstancePerSizeAndPrecision) {
  EXPECT_EQ(&real_fft<double>(256), &real_fft<double>(256));
  EXPECT_NE(&real_fft<double>(256), &real_fft<double>(257));
  EXPECT_EQ(&real_fft<float>(256), &real_fft<float>(256));
  EXPECT_EQ(real_fft<double>(257).bins(), 129u);
}

TEST(SignalFft, RejectsMismatchedSizes) {
  const auto& fft = real_fft<double>(16);
  std::vector<double> x(15);
  std::vector<std::complex<double>> X(9);
  EXPECT_THROW(fft.forward(x, X), Error);
  x.resize(16);
  X.resize(8);
  EXPECT_THROW(fft.inverse(X, x), Error);
  EXPECT_THROW(RealFft<double>(0), Error);
}

// Several threads plan (fresh sizes, so the planner lock is exercised) and execute at once;
// every thread must get exactly the single-threaded answer.
TEST(SignalFft, ConcurrentUseGivesIdenticalResults) {
  const auto x = load_golden("signal/fft_x_odd.npy").data;  // 999 samples
  const std::vector<std::size_t> sizes = {999, 640, 333, 128, 97};
  auto transform_all = [&](std::vector<std::vector<double>>& results) {
    for (int repeat = 0; repeat < 20; ++repeat) {
      results.clear();
      for (std::size_t n : sizes) {
        const auto& fft = real_fft<double>(n);
        std::vector<std::complex<double>> X(fft.bins());
        fft.forward(std::span(x).first(n), X);
        std::vector<double> back(n);
        fft.inverse(X, back);
        results.push_back(interleave(X));
        results.push_back(back);
      }
    }
  };
  constexpr int kThreads = 8;
  std::vector<std::vector<std::vector<double>>> per_thread(kThreads);
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) threads.emplace_back(transform_all, std::ref(per_thread[t]));
  for (auto& thread : threads) thread.join();
  std::vector<std::vector<double>> reference;
  transform_all(reference);
  for (int t = 0; t < kThreads; ++t) EXPECT_EQ(per_thread[t], reference) << "thread " << t;
  // The round trip itself is right, so "identical" is not "identically wrong".
  EXPECT_LT(max_scaled_error(reference[1], std::vector<double>(x.begin(), x.end())), 1e-13);
}

}  // namespace
}  // namespace haptex::signal
