#include "core/ar/poles.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace haptex::ar {

std::vector<std::complex<double>> ar_poles(std::span<const double> a) {
  if (a.empty() || a[0] == 0.0) throw failure("ar_poles: need a = [a0, ..., ap] with a0 != 0");
  for (double v : a)
    if (!std::isfinite(v)) throw failure("ar_poles: the coefficients must be finite");
  const Eigen::Index p = Eigen::Index(a.size()) - 1;
  if (p == 0) return {};
  // Companion matrix: first row -a1..-ap (normalised by a0), ones on the sub-diagonal.
  Eigen::MatrixXd companion = Eigen::MatrixXd::Zero(p, p);
  for (Eigen::Index j = 0; j < p; ++j) companion(0, j) = -a[std::size_t(j) + 1] / a[0];
  for (Eigen::Index i = 1; i < p; ++i) companion(i, i - 1) = 1.0;
  Eigen::EigenSolver<Eigen::MatrixXd> solver(companion, /*computeEigenvectors=*/false);
  if (solver.info() != Eigen::Success) throw failure("ar_poles: the eigenvalue iteration did not converge");
  const Eigen::VectorXcd values = solver.eigenvalues();
  return std::vector<std::complex<double>>(values.data(), values.data() + values.size());
}

double max_pole_radius(std::span<const double> a) {
  double radius = 0.0;
  for (const auto& pole : ar_poles(a)) radius = std::max(radius, std::abs(pole));
  return radius;
}

}  // namespace haptex::ar
