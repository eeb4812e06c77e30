#include "core/signal/butterworth.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "core/error.hpp"

// Every step follows scipy 1.10 (scipy/signal/_filter_design.py) operation by operation, so the
// coefficients agree to rounding: iirfilter -> buttap -> lp2lp_zpk -> bilinear_zpk -> zpk2sos.
namespace haptex::signal {
namespace {

using Complex = std::complex<double>;
using Roots = std::vector<Complex>;

// np.isreal: the imaginary part is exactly zero (true for everything _cplxreal puts in its real list).
bool is_real(Complex c) { return c.imag() == 0.0; }

std::size_t count_real(const Roots& roots) {
  return static_cast<std::size_t>(std::count_if(roots.begin(), roots.end(), is_real));
}

Complex take(Roots& roots, std::size_t index) {
  Complex value = roots[index];
  roots.erase(roots.begin() + static_cast<std::ptrdiff_t>(index));
  return value;
}

// Sorts [first, last) by a key, keeping ties in order (numpy's lexsort, and argsort on the short
// arrays zpk2sos sees, are stable).
template <typename It, typename Key>
void stable_sort_by(It first, It last, Key key) {
  std::stable_sort(first, last, [&](const auto& a, const auto& b) { return key(a) < key(b); });
}

// scipy's _cplxreal: conjugate pairs become one value with positive imaginary part (sorted by real
// part, then imaginary part), followed by the real values in ascending order.
Roots cplxreal(Roots z) {
  constexpr double tol = 100 * std::numeric_limits<double>::epsilon();
  std::stable_sort(z.begin(), z.end(), [](Complex a, Complex b) {
    return a.real() != b.real() ? a.real() < b.real() : std::abs(a.imag()) < std::abs(b.imag());
  });
  Roots real, positive, negative;
  for (Complex c : z) {
    if (std::abs(c.imag()) <= tol * std::abs(c))
      real.emplace_back(c.real(), 0.0);
    else
      (c.imag() > 0 ? positive : negative).push_back(c);
  }
  if (positive.size() != negative.size())
    throw failure("zpk_to_sos: a complex root has no matching conjugate");
  // Within runs of (nearly) equal real part, order by the size of the imaginary part.
  const std::size_t n = positive.size();
  for (std::size_t start = 0; start + 1 < n;) {
    std::size_t stop = start;
    while (stop + 1 < n && positive[stop + 1].real() - positive[stop].real() <= tol * std::abs(positive[stop]))
      ++stop;
    if (stop > start) {
      auto by_imag = [](Complex c) { return std::abs(c.imag()); };
      stable_sort_by(positive.begin() + static_cast<std::ptrdiff_t>(start),
                     positive.begin() + static_cast<std::ptrdiff_t>(stop + 1), by_imag);
      stable_sort_by(negative.begin() + static_cast<std::ptrdiff_t>(start),
                     negative.begin() + static_cast<std::ptrdiff_t>(stop + 1), by_imag);
    }
    start = stop + 1;
  }
  Roots out;
  for (std::size_t i = 0; i < n; ++i) {
    if (std::abs(positive[i] - std::conj(negative[i])) > tol * std::abs(negative[i]))
      throw failure("zpk_to_sos: a complex root has no matching conjugate");
    out.push_back((positive[i] + std::conj(negative[i])) / 2.0);  // averages out rounding in the pair
  }
  out.insert(out.end(), real.begin(), real.end());
  return out;
}

// Digital filters: the "worst" pole is the one closest to the unit circle (first one on ties).
std::size_t idx_worst(const Roots& p) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < p.size(); ++i)
    if (std::abs(1.0 - std::abs(p[i])) < std::abs(1.0 - std::abs(p[best]))) best = i;
  return best;
}

enum class Which { real, complex, any };

// scipy's _nearest_real_complex_idx: the closest element of `from` to `to` of the requested kind.
std::size_t nearest_idx(const Roots& from, Complex to, Which which) {
  std::vector<std::size_t> order(from.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  stable_sort_by(order.begin(), order.end(), [&](std::size_t i) { return std::abs(from[i] - to); });
  for (std::size_t i : order)
    if (which == Which::any || is_real(from[i]) == (which == Which::real)) return i;
  throw failure("zpk_to_sos: no zero of the required kind left to pair");
}

// numpy.poly: coefficients of prod (x - r), highest power first; real part, since the roots
// of one section are real or a conjugate pair.
std::vector<double> poly(const Roots& roots) {
  std::vector<Complex> c = {1.0};
  for (Complex r : roots) {
    std::vector<Complex> next(c.size() + 1, 0.0);
    for (std::size_t i = 0; i < c.size(); ++i) {
      next[i] += c[i];
      next[i + 1] += c[i] * -r;
    }
    c = std::move(next);
  }
  std::vector<double> out;
  for (Complex v : c) out.push_back(v.real());
  return out;
}

// scipy's _single_zpksos: numerator and denominator right-aligned in their three slots.
Section single_section(const Roots& z, const Roots& p) {
  Section s{};
  const auto b = poly(z);
  const auto a = poly(p);
  std::copy(b.begin(), b.end(), s.begin() + static_cast<std::ptrdiff_t>(3 - b.size()));
  std::copy(a.begin(), a.end(), s.begin() + static_cast<std::ptrdiff_t>(6 - a.size()));
  return s;
}

// One pass of zpk2sos's loop: removes the worst pole and the roots paired with it.
Section next_section(Roots& p, Roots& z) {
  const Complex p1 = take(p, idx_worst(p));
  if (is_real(p1) && count_real(p) == 0) {
    // The last real pole: a first-order section with its nearest real zero.
    const Complex z1 = take(z, nearest_idx(z, p1, Which::real));
    return single_section({z1, 0.0}, {p1, 0.0});
  }
  if (p.size() + 1 == z.size() && !is_real(p1) && count_real(p) == 1 && count_real(z) == 1) {
    // One real pole and one real zero remain for later: this complex pole must take a complex zero.
    const Complex z1 = take(z, nearest_idx(z, p1, Which::complex));
    return single_section({z1, std::conj(z1)}, {p1, std::conj(p1)});
  }
  Complex p2 = std::conj(p1);
  if (is_real(p1)) {
    Roots reals;
    std::vector<std::size_t> real_index;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (is_real(p[i])) {
        reals.push_back(p[i]);
        real_index.push_back(i);
      }
    p2 = take(p, real_index[idx_worst(reals)]);
  }
  if (z.empty()) return single_section({}, {p1, p2});
  const Complex z1 = take(z, nearest_idx(z, p1, Which::any));
  if (!is_real(z1)) return single_section({z1, std::conj(z1)}, {p1, p2});
  if (z.empty()) return single_section({z1}, {p1, p2});
  const Complex z2 = take(z, nearest_idx(z, p1, Which::real));
  return single_section({z1, z2}, {p1, p2});
}

}  // namespace

Sos zpk_to_sos(Zpk zpk) {
  Roots& z = zpk.zeros;
  Roots& p = zpk.poles;
  if (z.empty() && p.empty()) return {Section{zpk.gain, 0, 0, 1, 0, 0}};
  // 'nearest' pairing: as many zeros as poles, and an even count of each (extra roots at the origin).
  const std::size_t count = std::max(z.size(), p.size());
  p.resize(count, 0.0);
  z.resize(count, 0.0);
  const std::size_t sections = (count + 1) / 2;
  if (count % 2 == 1) {
    p.push_back(0.0);
    z.push_back(0.0);
  }
  z = cplxreal(z);
  p = cplxreal(p);
  // Built from the last section back, so the poles closest to the unit circle end up last.
  Sos sos(sections);
  for (std::size_t si = sections; si-- > 0;) sos[si] = next_section(p, z);
  for (int i = 0; i < 3; ++i) sos[0][i] *= zpk.gain;
  return sos;
}

Sos butter_lowpass(int order, double wn) {
  if (order < 1) throw failure("Butterworth design: order " + std::to_string(order) + " must be at least 1");
  if (!(wn > 0.0 && wn < 1.0))
    throw failure("Butterworth design: cut-off " + std::to_string(wn) +
                  " must lie strictly between 0 and 1 (a fraction of Nyquist)");
  const double pi = std::numbers::pi;
  // buttap: unit-cutoff analog poles; m = 0 (odd orders) gives an exactly real pole.
  Roots poles;
  for (int m = -order + 1; m < order; m += 2) poles.push_back(-std::exp(Complex(0.0, pi * m / (2.0 * order))));
  // Pre-warp with scipy's fs = 2 convention, then lp2lp_zpk.
  const double fs = 2.0;
  const double warped = 2.0 * fs * std::tan(pi * wn / fs);
  for (Complex& pole : poles) pole *= warped;
  const double analog_gain = std::pow(warped, order);
  // bilinear_zpk: the N zeros at infinity move to z = -1.
  const double fs2 = 2.0 * fs;
  Complex denominator = 1.0;
  for (Complex& pole : poles) {
    denominator *= fs2 - pole;
    pole = (fs2 + pole) / (fs2 - pole);
  }
  Zpk digital;
  digital.poles = poles;
  digital.zeros.assign(static_cast<std::size_t>(order), -1.0);
  digital.gain = analog_gain * (1.0 / denominator).real();
  return zpk_to_sos(std::move(digital));
}

Sos butter_lowpass_hz(int order, double cutoff_hz, double sample_rate_hz) {
  if (!(sample_rate_hz > 0.0))
    throw failure("Butterworth design: sample rate " + std::to_string(sample_rate_hz) + " Hz must be positive");
  if (!(cutoff_hz > 0.0 && cutoff_hz < sample_rate_hz / 2))
    throw failure("Butterworth design: cut-off " + std::to_string(cutoff_hz) + " Hz must lie between 0 and " +
                  std::to_string(sample_rate_hz / 2) + " Hz (Nyquist)");
  return butter_lowpass(order, 2.0 * cutoff_hz / sample_rate_hz);
}

}  // namespace haptex::signal
