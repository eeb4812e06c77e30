#include "predict/dense_kernel.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"

#if defined(__x86_64__)
#include <immintrin.h>
#define HAPTEX_X86_KERNELS 1
#endif

namespace haptex::predict {
namespace {

#ifdef HAPTEX_X86_KERNELS

// The four columns' share of eight rows of y: y + c0 x0 + c1 x1 + c2 x2 + c3 x3, in two chains.
struct FourColumns {
  __m256 x0, x1, x2, x3;
  __attribute__((target("avx2,fma"), always_inline)) __m256 add_to(__m256 y, __m256 c0, __m256 c1, __m256 c2,
                                                                    __m256 c3) const {
    const __m256 a = _mm256_fmadd_ps(c2, x2, _mm256_fmadd_ps(c0, x0, y));
    const __m256 b = _mm256_fmadd_ps(c3, x3, _mm256_mul_ps(c1, x1));
    return _mm256_add_ps(a, b);
  }
};

// y = W x + b, W column-major (rows m, columns n, leading dimension ld), four columns a step so that
// each pass over y reads four columns of W: W is most of the memory traffic (35 000 floats for the
// default model, in L2 not L1). A column whose x is exactly zero adds nothing and is not read: after a
// ReLU many inputs are zero (84 % of the trained default model's 256 hidden units; docs/predict.md).
// The rows past the last whole eight go through masked loads.
__attribute__((target("avx2,fma"))) void gemv_avx2(const float* w, long ld, long m, long n, const float* x, const float* b,
                                                   float* y) {
  const long full = m / 8 * 8;
  static constexpr int kLanes[16] = {-1, -1, -1, -1, -1, -1, -1, -1, 0, 0, 0, 0, 0, 0, 0, 0};
  const __m256i tail = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(kLanes + 8 - (m - full)));
  for (long i = 0; i < full; i += 8) _mm256_storeu_ps(y + i, _mm256_loadu_ps(b + i));
  // The rows past the last whole eight stay in a register until the end: masked stores are slow.
  __m256 rest = _mm256_maskload_ps(b + full, tail);
  const float* c[4];  // the next four columns with a non-zero x
  float xc[4];
  int k = 0;
  for (long j = 0; j < n; ++j) {
    if (x[j] == 0.0f) continue;
    c[k] = w + j * ld, xc[k] = x[j];
    if (++k < 4) continue;
    k = 0;
    const FourColumns f{_mm256_set1_ps(xc[0]), _mm256_set1_ps(xc[1]), _mm256_set1_ps(xc[2]), _mm256_set1_ps(xc[3])};
    for (long i = 0; i < full; i += 8)
      _mm256_storeu_ps(y + i, f.add_to(_mm256_loadu_ps(y + i), _mm256_loadu_ps(c[0] + i), _mm256_loadu_ps(c[1] + i),
                                       _mm256_loadu_ps(c[2] + i), _mm256_loadu_ps(c[3] + i)));
    if (full < m)
      rest = f.add_to(rest, _mm256_maskload_ps(c[0] + full, tail), _mm256_maskload_ps(c[1] + full, tail),
                      _mm256_maskload_ps(c[2] + full, tail), _mm256_maskload_ps(c[3] + full, tail));
  }
  if (full < m) _mm256_maskstore_ps(y + full, tail, rest);
  for (int last = 0; last < k; ++last)
    for (long i = 0; i < m; ++i) y[i] += c[last][i] * xc[last];
}

// e^a for a <= 0, eight at once: a = k ln 2 + r with |r| <= ln 2 / 2, e^r by its Taylor series to r^7
// (error under 1e-8 relative), 2^k through the exponent bits. Below -87 the result stays at e^-87 (about
// 1.6e-38) instead of leaving float's normal range: softplus there is below any vibration anyway.
__attribute__((target("avx2,fma"), always_inline)) inline __m256 exp_of_nonpositive(__m256 a) {
  a = _mm256_max_ps(_mm256_set1_ps(-87.0f), a);  // max returns its second operand for NaN: NaN stays
  const __m256 k = _mm256_round_ps(_mm256_mul_ps(a, _mm256_set1_ps(1.44269504088896341f)),
                                   _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC);
  __m256 r = _mm256_fnmadd_ps(k, _mm256_set1_ps(0.693359375f), a);  // ln 2 in two parts: k ln2_hi is exact
  r = _mm256_fnmadd_ps(k, _mm256_set1_ps(-2.12194440e-4f), r);
  __m256 p = _mm256_set1_ps(1.0f / 5040);
  for (const float c : {1.0f / 720, 1.0f / 120, 1.0f / 24, 1.0f / 6, 0.5f, 1.0f, 1.0f}) p = _mm256_fmadd_ps(p, r, _mm256_set1_ps(c));
  const __m256i two_to_k = _mm256_slli_epi32(_mm256_add_epi32(_mm256_cvtps_epi32(k), _mm256_set1_epi32(127)), 23);
  return _mm256_mul_ps(p, _mm256_castsi256_ps(two_to_k));
}

// log(1 + t) for 0 < t <= 1: 2 atanh(s) with s = t / (2 + t) <= 1/3, its odd series to s^15 (error under
// 1e-8 relative, and relative for the smallest t too).
__attribute__((target("avx2,fma"), always_inline)) inline __m256 log1p_of_unit(__m256 t) {
  const __m256 s = _mm256_div_ps(t, _mm256_add_ps(t, _mm256_set1_ps(2.0f)));
  const __m256 s2 = _mm256_mul_ps(s, s);
  __m256 p = _mm256_set1_ps(2.0f / 15);
  for (const float c : {2.0f / 13, 2.0f / 11, 2.0f / 9, 2.0f / 7, 2.0f / 5, 2.0f / 3, 2.0f}) p = _mm256_fmadd_ps(p, s2, _mm256_set1_ps(c));
  return _mm256_mul_ps(p, s);
}

// softplus(z) = max(z, 0) + log1p(e^-|z|), as activate() computes it, in place.
__attribute__((target("avx2,fma"))) void softplus_avx2(float* v, long n) {
  const __m256 sign = _mm256_set1_ps(-0.0f);
  long i = 0;
  for (; i + 8 <= n; i += 8) {
    const __m256 z = _mm256_loadu_ps(v + i);
    const __m256 t = exp_of_nonpositive(_mm256_or_ps(z, sign));  // -|z|
    _mm256_storeu_ps(v + i, _mm256_add_ps(_mm256_max_ps(_mm256_setzero_ps(), z), log1p_of_unit(t)));
  }
  for (; i < n; ++i) v[i] = std::max(v[i], 0.0f) + std::log1p(std::exp(-std::abs(v[i])));
}

bool has_avx2_fma() {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
}
#else
// Other processors run Eigen's path; these are never called.
bool has_avx2_fma() { return false; }
void gemv_avx2(const float*, long, long, long, const float*, const float*, float*) {}
void softplus_avx2(float*, long) {}
#endif

}  // namespace

bool dense_kernel_uses_avx2() {
  static const bool avx2 = has_avx2_fma();
  return avx2;
}

void dense_column(const Eigen::Ref<const Eigen::MatrixXf>& weight, const Eigen::VectorXf& in, const Eigen::VectorXf& bias,
                  Activation activation, Eigen::VectorXf& out) {
  if (in.size() != weight.cols() || bias.size() != weight.rows())
    throw failure("dense layer: " + std::to_string(weight.rows()) + " x " + std::to_string(weight.cols()) + " weights, " +
                  std::to_string(in.size()) + " inputs, " + std::to_string(bias.size()) + " biases");
  out.resize(weight.rows());  // nothing to do, and no allocation, when it has the size already
  if (dense_kernel_uses_avx2()) {
    gemv_avx2(weight.data(), weight.outerStride(), weight.rows(), weight.cols(), in.data(), bias.data(), out.data());
  } else {
    out.noalias() = weight * in;
    out += bias;
  }
  activate_fast(activation, out);
}

void activate_fast(Activation activation, Eigen::Ref<Eigen::MatrixXf> values) {
  if (activation != Activation::softplus || !dense_kernel_uses_avx2() || values.outerStride() != values.rows())
    return activate(activation, values);
  softplus_avx2(values.data(), long(values.size()));
}

}  // namespace haptex::predict
