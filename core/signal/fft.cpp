#include "core/signal/fft.hpp"

#include <fftw3.h>

#include <algorithm>
#include <limits>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "core/error.hpp"

namespace haptex::signal {
namespace {

// FFTW's planner (plan creation and destruction) is not thread-safe, in either precision.
// Constant-initialised, so it outlives every RealFft with static storage.
constinit std::mutex planner_mutex;

// One set of names per precision, so RealFft<T> is written once.
template <typename T>
struct Fftw;

template <>
struct Fftw<double> {
  using Plan = fftw_plan;
  using Complex = fftw_complex;
  static void* malloc(std::size_t bytes) { return fftw_malloc(bytes); }
  static void free(void* p) { fftw_free(p); }
  static Plan plan_r2c(int n, double* in, Complex* out, unsigned flags) {
    return fftw_plan_dft_r2c_1d(n, in, out, flags);
  }
  static Plan plan_c2r(int n, Complex* in, double* out, unsigned flags) {
    return fftw_plan_dft_c2r_1d(n, in, out, flags);
  }
  static void destroy(Plan p) { fftw_destroy_plan(p); }
  static void r2c(Plan p, double* in, Complex* out) { fftw_execute_dft_r2c(p, in, out); }
  static void c2r(Plan p, Complex* in, double* out) { fftw_execute_dft_c2r(p, in, out); }
  static int alignment_of(const void* p) { return fftw_alignment_of(static_cast<double*>(const_cast<void*>(p))); }
};

template <>
struct Fftw<float> {
  using Plan = fftwf_plan;
  using Complex = fftwf_complex;
  static void* malloc(std::size_t bytes) { return fftwf_malloc(bytes); }
  static void free(void* p) { fftwf_free(p); }
  static Plan plan_r2c(int n, float* in, Complex* out, unsigned flags) {
    return fftwf_plan_dft_r2c_1d(n, in, out, flags);
  }
  static Plan plan_c2r(int n, Complex* in, float* out, unsigned flags) {
    return fftwf_plan_dft_c2r_1d(n, in, out, flags);
  }
  static void destroy(Plan p) { fftwf_destroy_plan(p); }
  static void r2c(Plan p, float* in, Complex* out) { fftwf_execute_dft_r2c(p, in, out); }
  static void c2r(Plan p, Complex* in, float* out) { fftwf_execute_dft_c2r(p, in, out); }
  static int alignment_of(const void* p) { return fftwf_alignment_of(static_cast<float*>(const_cast<void*>(p))); }
};

// Two plans each way. New-array execute needs arrays aligned as the planner's were (FFTW's SIMD
// alignment, 16 bytes: every std::vector's data, as malloc aligns them): those run the SIMD plan,
// three times faster at N = 1000 (bench_evaluate); other pointers (a span into the middle of a
// signal) run the FFTW_UNALIGNED plan. Both are FFTW_ESTIMATE: the same plan every run, so the same
// result every run.
constexpr unsigned kAlignedFlags = FFTW_ESTIMATE, kUnalignedFlags = FFTW_ESTIMATE | FFTW_UNALIGNED;

template <typename T>
bool both_aligned(const void* a, const void* b) {
  return Fftw<T>::alignment_of(a) == 0 && Fftw<T>::alignment_of(b) == 0;
}

void check_size(const char* what, std::size_t got, std::size_t expected) {
  if (got != expected)
    throw failure(std::string("real FFT: ") + what + " has " + std::to_string(got) + " values, expected " +
                  std::to_string(expected));
}

}  // namespace

template <typename T>
RealFft<T>::RealFft(std::size_t n) : n_(n) {
  using F = Fftw<T>;
  if (n == 0 || n > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw failure("real FFT: size " + std::to_string(n) + " is out of range (1 .. 2^31-1)");
  // FFTW_ESTIMATE never touches the arrays, but the planner still wants real ones (fftw_malloc's:
  // aligned, which the aligned plans then require).
  T* real = static_cast<T*>(F::malloc(sizeof(T) * n));
  auto* spectrum = static_cast<typename F::Complex*>(F::malloc(sizeof(typename F::Complex) * bins()));
  std::lock_guard lock(planner_mutex);
  const int size = static_cast<int>(n);
  void* plans[2][2] = {};
  for (int aligned = 0; aligned < 2; ++aligned) {
    const unsigned flags = aligned ? kAlignedFlags : kUnalignedFlags;
    plans[aligned][0] = F::plan_r2c(size, real, spectrum, flags);
    plans[aligned][1] = F::plan_c2r(size, spectrum, real, flags);
  }
  F::free(real);
  F::free(spectrum);
  if (!plans[0][0] || !plans[0][1] || !plans[1][0] || !plans[1][1]) {
    for (auto& pair : plans)
      for (void* p : pair)
        if (p) F::destroy(static_cast<typename F::Plan>(p));
    throw failure("real FFT: FFTW could not plan a transform of size " + std::to_string(n));
  }
  forward_plan_ = plans[0][0], inverse_plan_ = plans[0][1];
  aligned_forward_plan_ = plans[1][0], aligned_inverse_plan_ = plans[1][1];
}

template <typename T>
RealFft<T>::~RealFft() {
  using F = Fftw<T>;
  std::lock_guard lock(planner_mutex);
  for (void* p : {forward_plan_, inverse_plan_, aligned_forward_plan_, aligned_inverse_plan_})
    F::destroy(static_cast<typename F::Plan>(p));
}

template <typename T>
void RealFft<T>::forward(std::span<const T> x, std::span<std::complex<T>> X) const {
  using F = Fftw<T>;
  check_size("forward input", x.size(), n_);
  check_size("forward output", X.size(), bins());
  // r2c plans preserve their input (FFTW's default for out-of-place r2c), so the cast is safe.
  void* plan = both_aligned<T>(x.data(), X.data()) ? aligned_forward_plan_ : forward_plan_;
  F::r2c(static_cast<typename F::Plan>(plan), const_cast<T*>(x.data()), reinterpret_cast<typename F::Complex*>(X.data()));
}

template <typename T>
void RealFft<T>::inverse(std::span<const std::complex<T>> X, std::span<T> x) const {
  using F = Fftw<T>;
  check_size("inverse input", X.size(), bins());
  check_size("inverse output", x.size(), n_);
  // c2r overwrites its input; work on a per-thread copy that only grows.
  thread_local std::vector<std::complex<T>> scratch;
  if (scratch.size() < X.size()) scratch.resize(X.size());
  std::copy(X.begin(), X.end(), scratch.begin());
  void* plan = both_aligned<T>(scratch.data(), x.data()) ? aligned_inverse_plan_ : inverse_plan_;
  F::c2r(static_cast<typename F::Plan>(plan), reinterpret_cast<typename F::Complex*>(scratch.data()), x.data());
  const T scale = T(1) / static_cast<T>(n_);
  for (T& v : x) v *= scale;
}

template <typename T>
const RealFft<T>& real_fft(std::size_t n) {
  // Never destroyed: returned references stay valid until exit, even for threads still running then.
  static constinit std::mutex cache_mutex;
  static auto* cache = new std::map<std::size_t, std::unique_ptr<RealFft<T>>>();
  std::lock_guard lock(cache_mutex);
  auto& slot = (*cache)[n];
  if (!slot) slot = std::make_unique<RealFft<T>>(n);
  return *slot;
}

template class RealFft<float>;
template class RealFft<double>;
template const RealFft<float>& real_fft<float>(std::size_t);
template const RealFft<double>& real_fft<double>(std::size_t);

}  // namespace haptex::signal
