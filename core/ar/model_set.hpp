#pragma once
// A HaTT piecewise-AR model set, as the model XML holds it (docs/convert.md). Plain data:
// convert/hatt_model_reader fills it, ar::PiecewiseArModel validates and renders it, and tests or
// the synthetic generator may build one by hand.
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace haptex::ar {

// One AR model, fitted at one (speed, force) vertex.
struct ArModel {
  int number = 0;                  // <modNum>, 1-based as in the file
  std::vector<double> ar_coeff;    // <ARcoeff>: [1, a1, ..., ap]
  std::vector<double> ar_lsf;      // <ARlsf>: p LSFs (rad/sample), the form HaTT interpolates
  std::vector<double> ma_coeff;    // <MAcoeff>: [1] for the pure-AR 10 kHz files
  std::vector<double> ma_lsf;      // <MAlsf>: empty for pure-AR
  double variance = 0.0;           // <var>: excitation variance, (m/s^2)^2; 0 on the zero-speed/force edges
  std::optional<double> gain;      // <gain>: ARMA models only
  double speed = 0.0;              // <speedMod>, mm/s
  double force = 0.0;              // <forceMod>, N
};

struct ModelSet {
  std::string source;              // file the set came from (named in error messages); may be empty
  int texture = 0;                 // <modelSet texture="N">
  std::string material;
  std::string accel_units = "m/s^2", speed_units = "mm/s", force_units = "N";
  double sample_rate_hz = 10000.0;
  double mu = 0.0;                 // kinetic friction coefficient
  double max_speed = 0.0;          // mm/s
  double max_force = 0.0;          // N
  int num_ar_coeff = 0;            // <numARCoeff>: the AR order p
  int num_ma_coeff = 0;            // <numMACoeff>
  // Vertex i of the triangulation sits at (speed_list[i], force_list[i]) and carries models[i].
  std::vector<double> speed_list, force_list;
  // Delaunay triangles as 0-based vertex indices (the file's 1-based <tri> values minus one).
  std::vector<std::array<std::size_t, 3>> triangles;
  std::vector<ArModel> models;
};

}  // namespace haptex::ar
