#pragma once
// Real FFT of one size over FFTW. A plan is made once per (size, precision) and shared;
// executing it is thread-safe (FFTW's new-array execute), only planning takes a lock.
#include <complex>
#include <cstddef>
#include <memory>
#include <span>

namespace haptex::signal {

template <typename T>
class RealFft {
 public:
  explicit RealFft(std::size_t n);
  ~RealFft();
  RealFft(const RealFft&) = delete;
  RealFft& operator=(const RealFft&) = delete;

  std::size_t size() const { return n_; }
  std::size_t bins() const { return n_ / 2 + 1; }
  // X[k] = sum_n x[n] e^{-2 pi i k n / N}, k = 0..N/2 (numpy.fft.rfft).
  void forward(std::span<const T> x, std::span<std::complex<T>> X) const;
  // x[n] = (1/N) sum_k X[k] e^{2 pi i k n / N} with Hermitian completion (numpy.fft.irfft).
  // The imaginary parts of X[0] and, for even N, X[N/2] are ignored.
  void inverse(std::span<const std::complex<T>> X, std::span<T> x) const;

 private:
  std::size_t n_;
  void* forward_plan_ = nullptr;  // FFTW_UNALIGNED: any arrays
  void* inverse_plan_ = nullptr;
  void* aligned_forward_plan_ = nullptr;  // SIMD: arrays on FFTW's alignment (fft.cpp)
  void* aligned_inverse_plan_ = nullptr;
};

// The shared transform for size N (created on first use, kept for the process' life).
template <typename T>
const RealFft<T>& real_fft(std::size_t n);

extern template class RealFft<float>;
extern template class RealFft<double>;

}  // namespace haptex::signal
