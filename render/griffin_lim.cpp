#include "render/griffin_lim.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>

#ifdef __SSE2__
#include <xmmintrin.h>
#endif

#include "core/error.hpp"
#include "core/random_seeds.hpp"
#include "core/signal/fft.hpp"
#include "dataset/window.hpp"

namespace haptex::render {
namespace {

using Complex = std::complex<double>;
using dataset::kWindowSamples;

void check_magnitudes(const MagnitudeFrames& s) {
  if (s.frames == 0 || s.bins != kReconstructionBins || s.values.size() != s.frames * s.bins)
    throw failure("Griffin-Lim: the magnitudes are " + std::to_string(s.frames) + " frames x " +
                  std::to_string(s.bins) + " bins (" + std::to_string(s.values.size()) + " values); expected at least " +
                  "one frame of " + std::to_string(kReconstructionBins) + " bins");
  for (std::size_t i = 0; i < s.values.size(); ++i)
    if (!(s.values[i] >= 0.0 && std::isfinite(s.values[i])))
      throw failure("Griffin-Lim: magnitude " + std::to_string(i % s.bins) + " of frame " + std::to_string(i / s.bins) +
                    " is " + std::to_string(s.values[i]) + "; magnitudes must be finite and non-negative");
}

void check_options(const GriffinLimOptions& options) {
  if (!(options.momentum >= 0.0 && options.momentum < 1.0))
    throw failure("Griffin-Lim: momentum " + std::to_string(options.momentum) + " is outside [0, 1)");
}

// X[k] = s[k] X[k] / |X[k]| (s[k] where X[k] is 0) for k from `first` on, on the real and imaginary
// parts as pairs (std::complex<T> is an array of two T, [complex.numbers]); the same operations, so
// the same values, as std::complex's.
template <typename T>
void impose_from(std::span<std::complex<T>> X, std::span<const T> s, std::size_t first) {
  T* p = reinterpret_cast<T*>(X.data());
  for (std::size_t k = first; k < X.size(); ++k) {
    const T re = p[2 * k], im = p[2 * k + 1];
    // sqrt(norm) rather than abs (hypot): 10x faster, and the magnitudes here are far from overflow.
    const T magnitude = std::sqrt(re * re + im * im);
    const bool phase = magnitude > T(0);
    const T factor = s[k] / (phase ? magnitude : T(1));
    p[2 * k] = phase ? re * factor : s[k];
    p[2 * k + 1] = phase ? im * factor : T(0);
  }
}

template <typename T>
void impose(std::span<std::complex<T>> X, std::span<const T> s) {
  impose_from(X, s, 0);
}

#ifdef __SSE2__
// The same for float, four coefficients at a time in SSE2 (every x86-64 has it; GCC leaves the loop
// scalar): sqrt, division and products are rounded as the scalar ones are, so the values are the same.
template <>
void impose<float>(std::span<std::complex<float>> X, std::span<const float> s) {
  float* p = reinterpret_cast<float*>(X.data());
  std::size_t k = 0;
  for (; k + 4 <= X.size(); k += 4) {
    const __m128 a = _mm_loadu_ps(p + 2 * k), b = _mm_loadu_ps(p + 2 * k + 4);  // re im re im, twice
    const __m128 re = _mm_shuffle_ps(a, b, _MM_SHUFFLE(2, 0, 2, 0)), im = _mm_shuffle_ps(a, b, _MM_SHUFFLE(3, 1, 3, 1));
    const __m128 target = _mm_loadu_ps(s.data() + k);
    const __m128 magnitude = _mm_sqrt_ps(_mm_add_ps(_mm_mul_ps(re, re), _mm_mul_ps(im, im)));
    const __m128 phase = _mm_cmpgt_ps(magnitude, _mm_setzero_ps());
    const __m128 factor = _mm_div_ps(target, _mm_or_ps(_mm_and_ps(phase, magnitude), _mm_andnot_ps(phase, _mm_set1_ps(1.0f))));
    const __m128 out_re = _mm_or_ps(_mm_and_ps(phase, _mm_mul_ps(re, factor)), _mm_andnot_ps(phase, target));
    const __m128 out_im = _mm_and_ps(phase, _mm_mul_ps(im, factor));
    _mm_storeu_ps(p + 2 * k, _mm_unpacklo_ps(out_re, out_im));
    _mm_storeu_ps(p + 2 * k + 4, _mm_unpackhi_ps(out_re, out_im));
  }
  impose_from(X, s, k);
}
#endif

// The working state of one reconstruction in precision T: coefficients t (whose phase is the
// estimate), the previous consistent coefficients c_{n-1}, and the signal. Sized once; the iterations
// only overwrite.
template <typename T>
class FastGriffinLim {
 public:
  using Complex = std::complex<T>;

  explicit FastGriffinLim(const MagnitudeFrames& s)
      : frames_(s.frames),
        magnitudes_(s.values.begin(), s.values.end()),
        fft_(signal::real_fft<T>(kWindowSamples)),
        x_(covered_samples(s.frames)),
        frame_(kWindowSamples),
        t_(s.values.size()),
        previous_(s.values.size()),
        spectrum_(kReconstructionBins) {
    const std::vector<double> window = signal::hann_periodic(kWindowSamples);
    window_.assign(window.begin(), window.end());
    gains_.resize(x_.size());
    for (std::size_t n = 0; n < gains_.size(); ++n) gains_[n] = T(synthesis_gain(window, n, s.frames));
  }

  void start(const GriffinLimOptions& options) {
    std::mt19937_64 engine(options.seed);
    for (std::size_t i = 0; i < t_.size(); ++i) {
      const double phase = options.initial_phase == InitialPhase::random ? 2.0 * std::numbers::pi * unit_draw(engine) : 0.0;
      t_[i] = Complex(std::polar(double(magnitudes_[i]), phase));
    }
  }

  // x = least-squares inverse of s e^{i arg t}.
  void synthesize() {
    std::fill(x_.begin(), x_.end(), T(0));
    for (std::size_t m = 0; m < frames_; ++m) {
      const auto t = frame_coefficients(t_, m);
      impose<T>(t, std::span<const T>(magnitudes_).subspan(m * kReconstructionBins, kReconstructionBins));
      fft_.inverse(t, frame_);
      T* out = x_.data() + m * kReconstructionHop;
      const T *w = window_.data(), *f = frame_.data();
#pragma omp simd
      for (std::size_t j = 0; j < kWindowSamples; ++j) out[j] += w[j] * f[j];
    }
    for (std::size_t n = 0; n < x_.size(); ++n) x_[n] *= gains_[n];
  }

  // c_n = STFT(x); t = c_n - beta c_{n-1}.
  void analyse(T beta) {
    for (std::size_t m = 0; m < frames_; ++m) {
      const T* in = x_.data() + m * kReconstructionHop;
      for (std::size_t j = 0; j < kWindowSamples; ++j) frame_[j] = window_[j] * in[j];
      fft_.forward(frame_, spectrum_);
      T* t = reinterpret_cast<T*>(frame_coefficients(t_, m).data());
      T* previous = reinterpret_cast<T*>(frame_coefficients(previous_, m).data());
      const T* c = reinterpret_cast<const T*>(spectrum_.data());
#pragma omp simd
      for (std::size_t k = 0; k < 2 * kReconstructionBins; ++k) {
        t[k] = c[k] - beta * previous[k];
        previous[k] = c[k];
      }
    }
  }

  std::vector<double> signal(std::size_t length) const {
    std::vector<double> out(length, 0.0);
    std::copy_n(x_.begin(), std::min(length, x_.size()), out.begin());
    return out;
  }

 private:
  static std::span<Complex> frame_coefficients(std::vector<Complex>& all, std::size_t m) {
    return std::span(all).subspan(m * kReconstructionBins, kReconstructionBins);
  }

  std::size_t frames_;
  std::vector<T> magnitudes_;
  const signal::RealFft<T>& fft_;
  std::vector<T> window_, gains_, x_, frame_;
  std::vector<Complex> t_, previous_, spectrum_;
};

template <typename T>
std::vector<double> reconstruct(const MagnitudeFrames& s, std::size_t length, const GriffinLimOptions& options) {
  const T beta = T(options.momentum / (1.0 + options.momentum));
  FastGriffinLim<T> state(s);
  state.start(options);
  for (std::size_t i = 0; i < options.iterations; ++i) {
    state.synthesize();
    state.analyse(beta);
  }
  state.synthesize();
  return state.signal(length);
}

}  // namespace

void impose_magnitude(std::span<Complex> X, std::span<const double> s) {
  if (X.size() != s.size())
    throw failure("impose magnitude: " + std::to_string(X.size()) + " coefficients but " + std::to_string(s.size()) +
                  " magnitudes");
  impose<double>(X, s);
}

std::vector<double> griffin_lim(const MagnitudeFrames& s, std::size_t length, const GriffinLimOptions& options) {
  check_magnitudes(s);
  check_options(options);
  return options.precision == Precision::float32 ? reconstruct<float>(s, length, options)
                                                 : reconstruct<double>(s, length, options);
}

}  // namespace haptex::render
