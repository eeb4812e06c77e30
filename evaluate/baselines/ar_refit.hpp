#pragma once
// The `ar-refit` baseline (the paper's): a HaTT-style piecewise AR model fitted to one
// material's train and val sections, rendered like a published model file.
//
// 1. Cut every section into 0.1 s segments, labelled with their median speed and force
//    (evaluate/baselines/ar_segments.hpp); silent or at-rest segments are skipped.
// 2. Group the segments on a grid in the (speed, force) plane, and fit one model per cell with
//    Burg's method over all its segments together: the reflection coefficients pool Burg's
//    numerator and denominator over the segments (no segment is joined to the next), so the fit
//    uses every sample once and stays stable (|k| <= 1 by Cauchy-Schwarz).
// 3. One AR order for the material (a model file has one numARCoeff): the order in
//    [min_order, max_order] (HaTT's files use 15..20) minimising the summed minimum description
//    length, sum over models of N log(var_p) + p log N, where N is the model's sample count.
//    Burg is order-recursive, so every candidate order comes from the same reflection
//    coefficients.
// 4. maxSpeed / maxForce: the largest speed and force labels used; HaTT's boundary models on
//    the rectangle's edges (evaluate/baselines/boundary_models.hpp); Delaunay triangles in the rectangle
//    scaled to the unit square (evaluate/baselines/delaunay.hpp).
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/ar/model_set.hpp"
#include "core/ar/piecewise_model.hpp"
#include "evaluate/baselines/ar_segments.hpp"

namespace haptex::evaluate {

struct ArRefitOptions {
  std::size_t segment_samples = 1000;       // 0.1 s at 10 kHz
  std::size_t min_order = 14, max_order = 20;  // equal values fix the order
  std::size_t min_segments = 10;            // usable segments the material needs at least
  std::size_t cells_per_axis = 8;           // grouping grid over the labels' bounding box
};

struct ArRefit {
  ar::ModelSet models;               // fitted models first, then the boundary copies
  std::size_t order = 0;             // the chosen AR order
  std::size_t fitted_models = 0;     // models fitted from data (the others are boundary copies)
  std::size_t segments = 0;          // segments the fit used
  std::size_t skipped_segments = 0;  // silent or at-rest segments left out
};

// Fits the model set of `material` (its display name, stored in the set) from its training
// pieces. Throws haptex::Error (bad input) naming the material, the samples it had and what is
// needed when the pieces give fewer than options.min_segments usable segments, and when the
// options are inconsistent (orders out of order, segments no longer than the order).
ArRefit refit_piecewise_ar(const std::string& material, std::span<const TrainingPiece> pieces,
                           const ArRefitOptions& options = {});

// `repeats` renderings of one speed / force trajectory from rest, the r-th with seed
// derive_seed(seed, r): the evaluator renders every test section this way (10 times).
std::vector<std::vector<double>> render_repeats(const ar::PiecewiseArModel& model, std::span<const double> speed,
                                                std::span<const double> force, std::size_t repeats,
                                                std::uint64_t seed);

}  // namespace haptex::evaluate
