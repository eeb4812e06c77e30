#pragma once
// The HaTT piecewise AR texture model: AR models at (speed, force) vertices of a Delaunay
// triangulation; between vertices the LSFs and variances are blended with barycentric weights.
// Blending LSFs (not coefficients) keeps the filter stable: a convex combination of strictly
// increasing LSF vectors in (0, pi) is again one.
#include <array>
#include <cstddef>
#include <vector>

#include "core/ar/model_set.hpp"

namespace haptex::ar {

// Where a (speed, force) point falls: a triangle and the barycentric weights of its vertices
// (each >= 0, summing to 1).
struct Barycentric {
  std::size_t triangle = 0;              // index into ModelSet::triangles
  std::array<std::size_t, 3> vertex{};   // 0-based model / vertex indices
  std::array<double, 3> weight{};
};

// The blended model at one operating point.
struct BlendedAr {
  double speed = 0.0, force = 0.0;  // after HaTT's clamping
  Barycentric where;
  std::vector<double> lsf;          // p blended LSFs
  std::vector<double> a;            // [1, a1, ..., ap] from the blended LSFs
  double variance = 0.0;            // blended excitation variance
};

class PiecewiseArModel {
 public:
  // Checks the set (counts, LSF ordering, vertex positions, triangle indices and areas; ARMA sets
  // are refused) and throws haptex::Error naming set.source and the offending model or triangle.
  explicit PiecewiseArModel(ModelSet set);

  const ModelSet& set() const { return set_; }
  std::size_t order() const { return order_; }

  // HaTT's saturation of a user's speed and force (see the .cpp for the toolkit's rule).
  // Throws haptex::Error for NaN or infinite input.
  std::array<double, 2> clamp(double speed, double force) const;

  // The triangle holding (speed, force), no clamping. A point outside every triangle gets the
  // nearest-fitting triangle with its negative weights set to zero and the rest renormalised.
  Barycentric locate(double speed, double force) const;

  // Clamp, locate, blend LSFs and variance, and convert to coefficients.
  BlendedAr blend(double speed, double force) const;

  // As blend(), reusing out's vectors and `work` so per-sample rendering does not allocate.
  void blend_into(double speed, double force, BlendedAr& out, std::vector<double>& work) const;

 private:
  ModelSet set_;
  std::size_t order_ = 0;
};

}  // namespace haptex::ar
