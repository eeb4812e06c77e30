#include "core/ar/lsf.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

#include "core/error.hpp"

namespace haptex::ar {
namespace {

constexpr double kPi = std::numbers::pi;

// c (length len) times (1 + b z^-1 + z^-2), in place; c must have room for len + 2 values.
// Descending i reads c[i-1], c[i-2] before they change.
void multiply_quadratic(double* c, std::size_t& len, double b) {
  c[len] = 0.0;
  c[len + 1] = 0.0;
  len += 2;
  for (std::size_t i = len - 1; i >= 2; --i) c[i] += b * c[i - 1] + c[i - 2];
  c[1] += b * c[0];
}

// prod over every other LSF (starting at `first`) of (1 - 2 cos(w) z^-1 + z^-2): a real, palindromic
// polynomial with roots exp(+-jw). Real quadratic factors leave no imaginary rounding dust to drop,
// unlike MATLAB's poly() of the complex roots.
std::size_t unit_circle_product(std::span<const double> lsf, std::size_t first, double* c) {
  std::size_t len = 1;
  c[0] = 1.0;
  for (std::size_t i = first; i < lsf.size(); i += 2) multiply_quadratic(c, len, -2.0 * std::cos(lsf[i]));
  return len;
}

// ---- poly -> LSF ----

// Quotient of c by (1 + s z^-shift) (shift 1 or 2), assuming the division is exact.
std::vector<double> deflate(const std::vector<double>& c, double s, std::size_t shift) {
  std::vector<double> q(c.size() - shift);
  for (std::size_t k = 0; k < q.size(); ++k) q[k] = c[k] - (k >= shift ? s * q[k - shift] : 0.0);
  // The deflated polynomial is palindromic in exact arithmetic; average away the rounding.
  for (std::size_t k = 0; k < q.size() / 2; ++k) q[k] = q[q.size() - 1 - k] = 0.5 * (q[k] + q[q.size() - 1 - k]);
  return q;
}

// A palindromic c of length 2m+1 equals, on the unit circle, z^-m times the real cosine series
// sum_k d_k cos(k w) with d_0 = c_m, d_k = 2 c_{m-k}.
std::vector<double> cosine_series(const std::vector<double>& c) {
  const std::size_t m = c.size() / 2;
  std::vector<double> d(m + 1);
  d[0] = c[m];
  for (std::size_t k = 1; k <= m; ++k) d[k] = 2.0 * c[m - k];
  return d;
}

// Clenshaw's recurrence in x = cos(w): the series is a Chebyshev sum.
double eval_cosine_series(const std::vector<double>& d, double w) {
  const double x = std::cos(w);
  double b1 = 0.0, b2 = 0.0;
  for (std::size_t k = d.size() - 1; k >= 1; --k) {
    const double b0 = d[k] + 2.0 * x * b1 - b2;
    b2 = b1;
    b1 = b0;
  }
  return d[0] + x * b1 - b2;
}

double bisect(const std::vector<double>& d, double lo, double hi, double f_lo) {
  for (;;) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) return mid;  // the bracket is one ulp wide
    const double f_mid = eval_cosine_series(d, mid);
    if (f_mid == 0.0) return mid;
    if ((f_mid < 0.0) == (f_lo < 0.0)) {
      lo = mid;
      f_lo = f_mid;
    } else {
      hi = mid;
    }
  }
}

// Roots in (0, pi) found on an n-interval grid: sign changes refined by bisection, exact zeros kept.
std::vector<double> roots_on_grid(const std::vector<double>& d, std::size_t n) {
  std::vector<double> roots;
  double w_prev = 0.0, f_prev = eval_cosine_series(d, 0.0);
  for (std::size_t j = 1; j <= n; ++j) {
    const double w = kPi * double(j) / double(n);
    const double f = eval_cosine_series(d, w);
    if (f == 0.0 && j < n) roots.push_back(w);
    if (f_prev * f < 0.0) roots.push_back(bisect(d, w_prev, w, f_prev));
    w_prev = w;
    f_prev = f;
  }
  return roots;
}

// The m = d.size() - 1 roots of the cosine series in (0, pi), refining the grid until all are
// bracketed. Returns fewer when A is not minimum phase (roots left the unit circle).
std::vector<double> cosine_series_roots(const std::vector<double>& d) {
  const std::size_t m = d.size() - 1;
  if (m == 0) return {};
  std::vector<double> roots;
  for (std::size_t n = 512 * (m + 1); n <= (std::size_t(1) << 21); n *= 4) {
    roots = roots_on_grid(d, n);
    if (roots.size() >= m) break;
  }
  return roots;
}

Error not_minimum_phase(const std::string& why) {
  return failure("poly_to_lsf: the polynomial has roots on or outside the unit circle (" + why +
                 "); LSFs exist only for a stable AR filter. Check the coefficients' sign convention "
                 "(a = [1, a1, ..., ap] for y[n] = e[n] - sum a_i y[n-i])");
}

}  // namespace

void check_lsf(std::span<const double> lsf, const std::string& what) {
  if (lsf.empty()) throw failure(what + ": no line spectral frequencies");
  for (std::size_t i = 0; i < lsf.size(); ++i) {
    const double prev = i == 0 ? 0.0 : lsf[i - 1];
    if (!std::isfinite(lsf[i]) || !(lsf[i] > prev) || !(lsf[i] < kPi)) {
      std::ostringstream os;
      os << what << ": value " << i + 1 << " (" << lsf[i] << ") breaks 0 < lsf(1) < ... < lsf(p) < pi, "
         << "which a stable AR filter needs. Fix the model so its LSFs are strictly increasing in (0, pi)";
      throw failure(os.str());
    }
  }
}

void lsf_to_poly_unchecked(std::span<const double> lsf, std::vector<double>& a, std::vector<double>& work) {
  const std::size_t p = lsf.size();
  work.resize(2 * (p + 3));
  double* q = work.data();
  double* r = work.data() + p + 3;  // the antisymmetric (P) side
  std::size_t q_len = unit_circle_product(lsf, 0, q);
  std::size_t r_len = unit_circle_product(lsf, 1, r);
  // The trivial roots: even p -> Q1 gets z = -1, P1 gets z = 1; odd p -> P1 gets z = +1 and -1.
  if (p % 2 == 0) {
    q[q_len] = 0.0;
    for (std::size_t i = q_len; i >= 1; --i) q[i] += q[i - 1];
    r[r_len] = 0.0;
    for (std::size_t i = r_len; i >= 1; --i) r[i] -= r[i - 1];
  } else {
    r[r_len] = r[r_len + 1] = 0.0;
    for (std::size_t i = r_len + 1; i >= 2; --i) r[i] -= r[i - 2];
  }
  a.resize(p + 1);
  for (std::size_t k = 0; k <= p; ++k) a[k] = 0.5 * (q[k] + r[k]);
}

std::vector<double> lsf_to_poly(std::span<const double> lsf) {
  check_lsf(lsf);
  std::vector<double> a, work;
  lsf_to_poly_unchecked(lsf, a, work);
  return a;
}

std::vector<double> poly_to_lsf(std::span<const double> a_in) {
  if (a_in.size() < 2) throw failure("poly_to_lsf: need a = [a0, a1, ..., ap] with p >= 1");
  if (a_in[0] == 0.0 || !std::isfinite(a_in[0])) throw failure("poly_to_lsf: a0 must be finite and non-zero");
  const std::size_t p = a_in.size() - 1;
  std::vector<double> a(p + 2, 0.0);
  for (std::size_t k = 0; k <= p; ++k) {
    a[k] = a_in[k] / a_in[0];
    if (!std::isfinite(a[k])) throw failure("poly_to_lsf: coefficient " + std::to_string(k) + " is not finite");
  }
  std::vector<double> sum(p + 2), diff(p + 2);
  for (std::size_t k = 0; k <= p + 1; ++k) {
    sum[k] = a[k] + a[p + 1 - k];
    diff[k] = a[k] - a[p + 1 - k];
  }
  const bool even = p % 2 == 0;
  const std::vector<double> q = even ? deflate(sum, 1.0, 1) : sum;           // Q1 / (1 + z^-1)
  const std::vector<double> r = even ? deflate(diff, -1.0, 1) : deflate(diff, -1.0, 2);  // P1 / (1 - z^-1 or z^-2)
  const std::vector<double> q_roots = cosine_series_roots(cosine_series(q));
  const std::vector<double> r_roots = cosine_series_roots(cosine_series(r));
  if (q_roots.size() != q.size() / 2 || r_roots.size() != r.size() / 2)
    throw not_minimum_phase("too few roots of P1/Q1 on the unit circle");
  std::vector<double> lsf(p);
  for (std::size_t i = 0; i < p; ++i) lsf[i] = i % 2 == 0 ? q_roots[i / 2] : r_roots[i / 2];
  for (std::size_t i = 1; i < p; ++i)
    if (!(lsf[i] > lsf[i - 1])) throw not_minimum_phase("the roots of P1 and Q1 do not interlace");
  return lsf;
}

}  // namespace haptex::ar
