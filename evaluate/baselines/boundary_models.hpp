#pragma once
// HaTT's boundary models: the published model sets (all 60 10 kHz files) frame their fitted
// models with copies on the four edges of the rectangle [0, maxSpeed] x [0, maxForce], so that
// every speed and force the renderer clamps into it falls in a triangle. What the files show:
//   - force = 0 edge: speeds 0, s, 2s, 3s, 4s and maxSpeed, where s = 5 * floor(maxSpeed / 25)
//     mm/s (maxSpeed / 5 rounded down to 5 mm/s);
//   - speed = 0 edge: forces 0.5, 0.5 + f, ... (while <= maxForce - f) and maxForce, where
//     f = 0.25 * floor(maxForce / 1.25) N (maxForce / 5 rounded down to 0.25 N); these rules
//     place every boundary model of 52 of the 60 files (7 others have one force row more or
//     fewer at the top, their rule seems to use a maximum the files do not store, and Polyethylene
//     Foam steps by 0.2 N);
//   - speed = maxSpeed edge: the same forces, 0.5 + k f and maxForce;
//   - force = maxForce edge: speeds s, 2s, 3s, 4s.
// Each boundary model copies the LSFs and coefficients of the nearest fitted model by plain
// Euclidean distance in (mm/s, N) (so speed dominates; exact in all 52 files whose places match;
// maxSpeed and maxForce are the largest speed and force of a fitted model, so one fitted model
// lies on each maximum edge, in 5 files at the corner); models on the force = 0 and speed = 0
// edges have var = 0 (no touch or no motion: no vibration), those on the maxSpeed and maxForce
// edges keep the copied var. The corners (0, 0), (maxSpeed, 0) and (0, maxForce) are therefore
// silent and (maxSpeed, maxForce) is not.
#include <vector>

#include "core/ar/model_set.hpp"

namespace haptex::evaluate {

struct BoundaryVertex {
  double speed = 0.0;   // mm/s
  double force = 0.0;   // N
  bool silent = false;  // on the force = 0 or speed = 0 edge: var = 0
};

// HaTT's edge vertices for the given maxima, in the order listed above. Throws haptex::Error
// unless both maxima are finite and positive. Below 25 mm/s (1.25 N) the step is max / 5.
std::vector<BoundaryVertex> hatt_boundary_vertices(double max_speed, double max_force);

// Appends a boundary model to `set` for each vertex of hatt_boundary_vertices(set.max_speed,
// set.max_force) that does not coincide (within 1e-6 of the range) with a model already there.
// `set` must hold the fitted models only, with speed_list / force_list matching them; numbers
// (modNum) continue from theirs. Triangles are left to the caller. Throws haptex::Error when the
// set has no models or non-positive maxima.
void add_hatt_boundary_models(ar::ModelSet& set);

}  // namespace haptex::evaluate
