#pragma once
// Line spectral frequencies <-> AR polynomial, with MATLAB's lsf2poly / poly2lsf conventions
// (the HaTT models were fitted in MATLAB and store both forms).
//
// For A(z) = 1 + a1 z^-1 + ... + ap z^-p:
//   Q1(z) = A(z) + z^-(p+1) A(1/z)  (symmetric)      holds the 1st, 3rd, 5th, ... LSF;
//   P1(z) = A(z) - z^-(p+1) A(1/z)  (antisymmetric)  holds the 2nd, 4th, ... LSF.
// Even p: P1 also has z = 1 and Q1 z = -1. Odd p: P1 has z = +1 and z = -1.
// A = (P1 + Q1) / 2 without its last coefficient.
#include <span>
#include <string>
#include <vector>

namespace haptex::ar {

// lsf: p values, strictly increasing inside (0, pi). Returns a = [1, a1, ..., ap].
// Throws haptex::Error when the LSFs are not finite, not strictly increasing or outside (0, pi).
std::vector<double> lsf_to_poly(std::span<const double> lsf);

// Same, into `a` (resized to p + 1), reusing `work` as scratch: no allocation once the vectors
// have grown, for per-sample rendering. Does not validate: callers pass LSFs already checked.
void lsf_to_poly_unchecked(std::span<const double> lsf, std::vector<double>& a, std::vector<double>& work);

// a = [a0, a1, ..., ap], a0 != 0 (divided out, as MATLAB does), p >= 1. Returns the p LSFs in
// increasing order. The roots of P1 and Q1 are found on the unit circle as sign changes of real
// cosine series, refined by bisection to machine precision. Throws haptex::Error when A has a
// root on or outside the unit circle (the LSFs would not interlace).
std::vector<double> poly_to_lsf(std::span<const double> a);

// Throws haptex::Error unless lsf is non-empty, finite, strictly increasing and inside (0, pi).
// `what` names the LSF set in the message (e.g. "model 3 ARlsf").
void check_lsf(std::span<const double> lsf, const std::string& what = "LSFs");

}  // namespace haptex::ar
