#include "core/ar/piecewise_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/ar/lsf.hpp"
#include "core/error.hpp"

namespace haptex::ar {
namespace {

// HaTT renderer's saturation (Penn Haptic Texture Toolkit, AccSynthHashMatrix.cpp,
// AccSynthHashTable::HashAndInterp2): above the modelled maximum the value is set just inside it
// (max - 0.01, "slightly inside convex hull because of rounding errors"); below 0.05 it is set to
// 0.0001 ("essentially zero"); anything between is used as is. Our point location tolerates the
// hull's edge, but we keep the toolkit's numbers so rendered textures match its behaviour.
constexpr double kAboveMaxInset = 0.01;
constexpr double kNearZero = 0.05;
constexpr double kNearZeroValue = 0.0001;

double clamp_axis(double value, double max) {
  // Keep the inset inside (0, max] even for a tiny hand-made model set.
  if (value > max) return std::max(max - kAboveMaxInset, 0.5 * max);
  if (value < kNearZero) return std::min(kNearZeroValue, 0.5 * max);
  return value;
}

std::string file_of(const ModelSet& set) { return set.source.empty() ? std::string("<model set>") : set.source; }

std::string model_where(const ArModel& model, std::size_t i) {
  return "model " + std::to_string(i + 1) + " (modNum " + std::to_string(model.number) + ")";
}

bool close(double a, double b) { return std::abs(a - b) <= 1e-6 * (1.0 + std::abs(b)); }

// Barycentric weights of (x, y) in the triangle (x[k], y[k]); NaN weights for a degenerate one.
std::array<double, 3> barycentric(const std::array<double, 3>& x, const std::array<double, 3>& y, double px,
                                  double py) {
  const double det = (y[1] - y[2]) * (x[0] - x[2]) + (x[2] - x[1]) * (y[0] - y[2]);
  const double w0 = ((y[1] - y[2]) * (px - x[2]) + (x[2] - x[1]) * (py - y[2])) / det;
  const double w1 = ((y[2] - y[0]) * (px - x[2]) + (x[0] - x[2]) * (py - y[2])) / det;
  return {w0, w1, 1.0 - w0 - w1};
}

void check_sizes(const ModelSet& set) {
  const std::string file = file_of(set);
  if (set.models.empty()) throw input_error(file, "modelSet", "the set has no models", "Add <model> elements");
  if (set.speed_list.size() != set.models.size() || set.force_list.size() != set.models.size())
    throw input_error(file, "speedList/forceList",
                      "the vertex lists have " + std::to_string(set.speed_list.size()) + " and " +
                          std::to_string(set.force_list.size()) + " values for " +
                          std::to_string(set.models.size()) + " models",
                      "Give one speed and one force per model");
  if (!(set.max_speed > 0.0) || !(set.max_force > 0.0) || !std::isfinite(set.max_speed) ||
      !std::isfinite(set.max_force))
    throw input_error(file, "maxSpeed/maxForce", "the modelled maxima must be finite and positive",
                      "Fix maxSpeed and maxForce");
  if (set.triangles.empty()) throw input_error(file, "tri", "the set has no triangles", "Add <tri> elements");
  // Only HaTT's lower-rate files are ARMA; rendering them without their MA part would be wrong.
  if (set.num_ma_coeff > 0)
    throw input_error(file, "numMACoeff", "ARMA models (numMACoeff > 0) are not supported",
                      "Use the toolkit's 10 kHz pure-AR model files");
}

std::size_t check_models(const ModelSet& set) {
  const std::string file = file_of(set);
  const std::size_t p = set.num_ar_coeff > 0 ? std::size_t(set.num_ar_coeff) : set.models[0].ar_lsf.size();
  for (std::size_t i = 0; i < set.models.size(); ++i) {
    const ArModel& m = set.models[i];
    const std::string where = model_where(m, i);
    if (m.ar_lsf.size() != p)
      throw input_error(file, where + " ARlsf",
                        "has " + std::to_string(m.ar_lsf.size()) + " LSFs, the set's AR order is " + std::to_string(p),
                        "Give every model numARCoeff LSFs");
    try {
      check_lsf(m.ar_lsf, "ARlsf");
    } catch (const Error& e) {
      throw input_error(file, where, e.what(), "");
    }
    if (!std::isfinite(m.variance) || m.variance < 0.0)
      throw input_error(file, where + " var", "the variance must be finite and >= 0", "Fix <var>");
    if (!close(m.speed, set.speed_list[i]) || !close(m.force, set.force_list[i]))
      throw input_error(file, where,
                        "speedMod/forceMod (" + std::to_string(m.speed) + ", " + std::to_string(m.force) +
                            ") differ from vertex " + std::to_string(i + 1) + " of speedList/forceList",
                        "List the models in the order of speedList/forceList");
  }
  return p;
}

void check_triangles(const ModelSet& set) {
  const std::string file = file_of(set);
  const double scale = set.max_speed * set.max_force;
  for (std::size_t t = 0; t < set.triangles.size(); ++t) {
    const auto& tri = set.triangles[t];
    const std::string where = "tri " + std::to_string(t + 1);
    for (std::size_t v : tri)
      if (v >= set.models.size())
        throw input_error(file, where,
                          "vertex index " + std::to_string(v + 1) + " is outside 1.." + std::to_string(set.models.size()),
                          "Use 1-based model indices");
    const double area2 = (set.speed_list[tri[1]] - set.speed_list[tri[0]]) * (set.force_list[tri[2]] - set.force_list[tri[0]]) -
                         (set.speed_list[tri[2]] - set.speed_list[tri[0]]) * (set.force_list[tri[1]] - set.force_list[tri[0]]);
    if (!(std::abs(area2) > 1e-12 * scale))
      throw input_error(file, where, "the triangle has no area (collinear vertices)", "Fix the triangulation");
  }
}

}  // namespace

PiecewiseArModel::PiecewiseArModel(ModelSet set) : set_(std::move(set)) {
  check_sizes(set_);
  order_ = check_models(set_);
  check_triangles(set_);
}

std::array<double, 2> PiecewiseArModel::clamp(double speed, double force) const {
  if (!std::isfinite(speed) || !std::isfinite(force))
    throw failure("piecewise AR model " + file_of(set_) + ": speed and force must be finite (got " +
                  std::to_string(speed) + ", " + std::to_string(force) + ")");
  return {clamp_axis(speed, set_.max_speed), clamp_axis(force, set_.max_force)};
}

// The toolkit walks the triangulation (Devillers et al.'s visibility walk); with ~50 triangles a
// scan for the triangle whose smallest weight is largest is as fast and cannot get lost.
Barycentric PiecewiseArModel::locate(double speed, double force) const {
  Barycentric best;
  double best_min = -std::numeric_limits<double>::infinity();
  for (std::size_t t = 0; t < set_.triangles.size(); ++t) {
    const auto& tri = set_.triangles[t];
    const std::array<double, 3> x{set_.speed_list[tri[0]], set_.speed_list[tri[1]], set_.speed_list[tri[2]]};
    const std::array<double, 3> y{set_.force_list[tri[0]], set_.force_list[tri[1]], set_.force_list[tri[2]]};
    const auto w = barycentric(x, y, speed, force);
    const double smallest = std::min({w[0], w[1], w[2]});
    if (smallest > best_min) {
      best_min = smallest;
      best = {t, tri, w};
    }
    if (smallest >= 0.0) break;  // inside (or on the edge of) this triangle
  }
  // Outside the triangulation (or a rounding hair outside an edge): stay a convex combination.
  double sum = 0.0;
  for (double& w : best.weight) sum += (w = std::max(w, 0.0));
  for (double& w : best.weight) w /= sum;
  return best;
}

void PiecewiseArModel::blend_into(double speed, double force, BlendedAr& out, std::vector<double>& work) const {
  const auto clamped = clamp(speed, force);
  out.speed = clamped[0];
  out.force = clamped[1];
  out.where = locate(out.speed, out.force);
  out.lsf.assign(order_, 0.0);
  out.variance = 0.0;
  for (std::size_t k = 0; k < 3; ++k) {
    const ArModel& m = set_.models[out.where.vertex[k]];
    const double w = out.where.weight[k];
    for (std::size_t i = 0; i < order_; ++i) out.lsf[i] += w * m.ar_lsf[i];
    out.variance += w * m.variance;
  }
  lsf_to_poly_unchecked(out.lsf, out.a, work);
}

BlendedAr PiecewiseArModel::blend(double speed, double force) const {
  BlendedAr out;
  std::vector<double> work;
  blend_into(speed, force, out, work);
  return out;
}

}  // namespace haptex::ar
