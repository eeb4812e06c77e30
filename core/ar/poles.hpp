#pragma once
// Poles of an all-pole filter 1 / A(z): the roots of z^p + a1 z^(p-1) + ... + ap.
#include <complex>
#include <span>
#include <vector>

namespace haptex::ar {

// a = [a0, a1, ..., ap] with a0 != 0. Eigenvalues of the companion matrix (Eigen), in no
// particular order. Throws haptex::Error when a0 is zero or a value is not finite.
std::vector<std::complex<double>> ar_poles(std::span<const double> a);

// Largest pole modulus; 0 for p = 0. The filter is stable when it is < 1.
double max_pole_radius(std::span<const double> a);

}  // namespace haptex::ar
