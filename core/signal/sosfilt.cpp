#include "core/signal/sosfilt.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"

// Follows scipy 1.10 (scipy/signal/_signaltools.py and _sosfilt.pyx).
namespace haptex::signal {
namespace {

void check_sections(const Sos& sos, const char* who) {
  if (sos.empty()) throw failure(std::string(who) + ": the filter has no sections");
  for (std::size_t i = 0; i < sos.size(); ++i)
    if (sos[i][3] != 1.0)
      throw failure(std::string(who) + ": section " + std::to_string(i) + " has a0 = " +
                    std::to_string(sos[i][3]) + ", expected 1");
}

// scipy.signal.lfilter_zi for one biquad: the state z with z = A z + B for a unit step, i.e.
// [[1 + a1, -1], [a2, 1]] z = [b1 - a1 b0, b2 - a2 b0], solved with partial pivoting as LAPACK does.
std::array<double, 2> biquad_zi(const Section& s) {
  const double b0 = s[0], b1 = s[1], b2 = s[2], a1 = s[4], a2 = s[5];
  double m[2][2] = {{1.0 + a1, -1.0}, {a2, 1.0}};
  double rhs[2] = {b1 - a1 * b0, b2 - a2 * b0};
  if (std::abs(m[1][0]) > std::abs(m[0][0])) {
    std::swap(m[0], m[1]);
    std::swap(rhs[0], rhs[1]);
  }
  if (m[0][0] == 0.0) throw failure("sosfilt_zi: a section has no steady state (a pole at z = 1)");
  // LAPACK's dgetrf2 scales the pivot column by the pivot's reciprocal; doing the same keeps
  // the result bit-identical to scipy's (rounding differs by 1e-12 near z = 1 otherwise).
  const double l = m[1][0] * (1.0 / m[0][0]);
  const double u11 = m[1][1] - l * m[0][1];
  if (u11 == 0.0) throw failure("sosfilt_zi: a section has no steady state (a pole at z = 1)");
  const double z1 = (rhs[1] - l * rhs[0]) / u11;
  const double z0 = (rhs[0] - m[0][1] * z1) / m[0][0];
  return {z0, z1};
}

// 2 x[0] - x[padlen..1] + x + 2 x[-1] - x[-2..-(padlen+1)]: the signal mirrored about its end points.
std::vector<double> odd_extension(std::span<const double> x, std::size_t padlen) {
  const std::size_t n = x.size();
  std::vector<double> ext;
  ext.reserve(n + 2 * padlen);
  for (std::size_t i = padlen; i >= 1; --i) ext.push_back(2 * x[0] - x[i]);
  ext.insert(ext.end(), x.begin(), x.end());
  for (std::size_t i = 2; i <= padlen + 1; ++i) ext.push_back(2 * x[n - 1] - x[n - i]);
  return ext;
}

std::vector<std::array<double, 2>> scaled(std::vector<std::array<double, 2>> zi, double factor) {
  for (auto& state : zi)
    for (double& v : state) v *= factor;
  return zi;
}

// The samples a pass filters in place: forward through a buffer, or backward from its end, so the
// backward pass of sosfiltfilt needs no reversed copy.
struct Samples {
  double* first;
  std::ptrdiff_t step;  // +1 or -1
  std::size_t size;
  double& operator[](std::size_t i) const { return first[std::ptrdiff_t(i) * step]; }
  Samples after(std::size_t skip) const { return {first + std::ptrdiff_t(skip) * step, step, size - skip}; }
};

// A section's last two inputs and outputs: x1, x2, y1, y2.
using History = std::array<double, 4>;

History shifted(const History& h, double in, double out) { return {in, h[0], out, h[2]}; }

double direct_form(const Section& c, double in, const History& h) {
  return (c[0] * in + c[1] * h[0] + c[2] * h[1] - c[5] * h[3]) - c[4] * h[2];
}

void single_pass(const Section& c, Samples x, History& h) {
  History local = h;
  for (std::size_t i = 0; i < x.size; ++i) {
    double& sample = x[i];
    const double out = direct_form(c, sample, local);
    local = shifted(local, sample, out);
    sample = out;
  }
  h = local;
}

// Sections c then d over the signal in one loop: d takes c's output sample by sample.
void pair_pass(const Section& c, const Section& d, Samples x, History& hc, History& hd) {
  History a = hc, b = hd;
  for (std::size_t i = 0; i < x.size; ++i) {
    double& sample = x[i];
    const double mid = direct_form(c, sample, a);
    const double out = direct_form(d, mid, b);
    a = shifted(a, sample, mid);
    b = shifted(b, mid, out);
    sample = out;
  }
  hc = a, hd = b;
}

void filter(const Sos& sos, Samples x, std::vector<std::array<double, 2>>& zi) {
  check_sections(sos, "sosfilt");
  if (zi.size() != sos.size())
    throw failure("sosfilt: " + std::to_string(zi.size()) + " initial states for " + std::to_string(sos.size()) +
                  " sections");
  const std::size_t sections = sos.size();
  // Each section's history, for the direct form below.
  std::vector<History> past(sections);
  // The first two samples as scipy filters them, from the state zi holds.
  const std::size_t head = std::min<std::size_t>(2, x.size);
  for (std::size_t i = 0; i < head; ++i) {
    double current = x[i];
    for (std::size_t s = 0; s < sections; ++s) {
      const Section& c = sos[s];
      auto& z = zi[s];
      const double out = c[0] * current + z[0];
      z[0] = c[1] * current - c[4] * out + z[1];
      z[1] = c[2] * current - c[5] * out;
      past[s] = shifted(past[s], current, out);
      current = out;
    }
    x[i] = current;
  }
  if (x.size < 2) return;
  // Then in direct form I, the same filter summed another way, two sections per pass with their
  // state in registers: only one multiply and one subtraction wait for each section's previous
  // output, which sets the speed of a recursive filter, and the two sections' chains overlap.
  // Results agree with scipy's to 1e-9 (tests/core/signal_sosfilt_test.cpp).
  std::size_t pair = 0;
  for (; pair + 1 < sections; pair += 2) pair_pass(sos[pair], sos[pair + 1], x.after(2), past[pair], past[pair + 1]);
  if (pair < sections) single_pass(sos[pair], x.after(2), past[pair]);
  // The state scipy's form would hold after the last sample, for a caller that filters on.
  for (std::size_t s = 0; s < sections; ++s) {
    const Section& c = sos[s];
    const History& p = past[s];
    zi[s] = {c[1] * p[0] - c[4] * p[2] + (c[2] * p[1] - c[5] * p[3]), c[2] * p[0] - c[5] * p[2]};
  }
}

}  // namespace

std::vector<std::array<double, 2>> sosfilt_zi(const Sos& sos) {
  check_sections(sos, "sosfilt_zi");
  std::vector<std::array<double, 2>> zi;
  // Each section starts in the steady state of the step that reaches it: the product of the
  // DC gains b.sum() / a.sum() of the sections before it.
  double scale = 1.0;
  for (const Section& s : sos) {
    auto state = biquad_zi(s);
    zi.push_back({scale * state[0], scale * state[1]});
    scale *= (s[0] + s[1] + s[2]) / (s[3] + s[4] + s[5]);
  }
  return zi;
}

void sosfilt(const Sos& sos, std::span<double> x, std::vector<std::array<double, 2>>& zi) {
  filter(sos, Samples{x.data(), 1, x.size()}, zi);
}

std::size_t sosfiltfilt_padlen(const Sos& sos) {
  auto zero_count = [&](int column) {
    return static_cast<std::size_t>(
        std::count_if(sos.begin(), sos.end(), [&](const Section& s) { return s[column] == 0.0; }));
  };
  // Odd orders carry a padded zero and pole at the origin (b2 = 0, a2 = 0), which scipy discounts.
  const std::size_t taps = 2 * sos.size() + 1 - std::min(zero_count(2), zero_count(5));
  return 3 * taps;
}

std::vector<double> sosfiltfilt(const Sos& sos, std::span<const double> x) {
  check_sections(sos, "sosfiltfilt");
  const std::size_t padlen = sosfiltfilt_padlen(sos);
  if (x.size() <= padlen)
    throw failure("sosfiltfilt: the signal has " + std::to_string(x.size()) +
                  " samples; zero-phase filtering with this filter needs more than " + std::to_string(padlen));
  const auto zi = sosfilt_zi(sos);
  // One buffer, filtered forward and then backward in place, its padding cut off at the end (one move
  // of the samples): reversed copies and a second buffer cost more than both passes (perf).
  std::vector<double> y = odd_extension(x, padlen);
  // Start each pass in the steady state of its first sample, so the edges do not ring.
  auto state = scaled(zi, y.front());
  filter(sos, Samples{y.data(), 1, y.size()}, state);
  state = scaled(zi, y.back());
  filter(sos, Samples{y.data() + y.size() - 1, -1, y.size()}, state);
  y.erase(y.begin(), y.begin() + static_cast<std::ptrdiff_t>(padlen));
  y.resize(x.size());
  return y;
}

}  // namespace haptex::signal
