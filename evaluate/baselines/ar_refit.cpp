#include "evaluate/baselines/ar_refit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/ar/lsf.hpp"
#include "core/ar/texture_renderer.hpp"
#include "core/error.hpp"
#include "core/random_seeds.hpp"
#include "evaluate/baselines/boundary_models.hpp"
#include "evaluate/baselines/delaunay.hpp"

namespace haptex::evaluate {
namespace {

// Burg's lattice over several separate stretches of signal at once: stage m's reflection
// coefficient minimises the summed forward and backward error energy of all of them.
struct PooledBurg {
  std::vector<double> reflection;  // k1 .. k_max_order
  double energy = 0.0;             // x'x / N over all stretches (arburg's E0)
  std::size_t samples = 0;         // N
};

// One stretch's forward (f) and backward (b) prediction errors, updated stage by stage.
struct Lattice {
  std::vector<double> f, b;
};

// Stage m's sums over one stretch: numerator and denominator of the reflection coefficient.
void accumulate(const Lattice& s, std::size_t m, double& num, double& den) {
  for (std::size_t t = m; t < s.f.size(); ++t) {
    num += s.b[t - 1] * s.f[t];
    den += s.f[t] * s.f[t] + s.b[t - 1] * s.b[t - 1];
  }
}

// Apply reflection k at stage m; descending t keeps b[t - 1] at stage m - 1 until it is used.
void advance(Lattice& s, std::size_t m, double k) {
  for (std::size_t t = s.f.size(); t-- > m;) {
    const double forward = s.f[t];
    s.f[t] += k * s.b[t - 1];
    s.b[t] = s.b[t - 1] + k * forward;
  }
}

PooledBurg pooled_burg(const std::vector<std::span<const double>>& stretches, std::size_t order) {
  PooledBurg out;
  std::vector<Lattice> lattices;
  for (const auto& x : stretches) {
    lattices.push_back({std::vector<double>(x.begin(), x.end()), std::vector<double>(x.begin(), x.end())});
    for (double v : x) out.energy += v * v;
    out.samples += x.size();
  }
  out.energy /= double(out.samples);
  for (std::size_t m = 1; m <= order; ++m) {
    double num = 0.0, den = 0.0;
    for (const Lattice& s : lattices) accumulate(s, m, num, den);
    // A stretch predicted perfectly leaves nothing to model: stop adding structure.
    const double k = den > 0.0 ? -2.0 * num / den : 0.0;
    for (Lattice& s : lattices) advance(s, m, k);
    out.reflection.push_back(k);
  }
  return out;
}

// Step-up recursion: the order-p polynomial [1, a1, .., ap] from the first p reflections.
std::vector<double> polynomial(const PooledBurg& fit, std::size_t p) {
  std::vector<double> a{1.0};
  for (std::size_t m = 1; m <= p; ++m) {
    const double k = fit.reflection[m - 1];
    std::vector<double> next(m + 1);
    next[0] = 1.0;
    for (std::size_t i = 1; i < m; ++i) next[i] = a[i] + k * a[m - i];
    next[m] = k;
    a = std::move(next);
  }
  return a;
}

double variance(const PooledBurg& fit, std::size_t p) {
  double v = fit.energy;
  for (std::size_t m = 0; m < p; ++m) v *= 1.0 - fit.reflection[m] * fit.reflection[m];
  return v;
}

// Minimum description length summed over the models; ties go to the lower order.
std::size_t choose_order(const std::vector<PooledBurg>& fits, const ArRefitOptions& o) {
  std::size_t best = o.min_order;
  double best_score = std::numeric_limits<double>::infinity();
  for (std::size_t p = o.min_order; p <= o.max_order; ++p) {
    double score = 0.0;
    for (const PooledBurg& fit : fits) {
      const double n = double(fit.samples);
      score += n * std::log(std::max(variance(fit, p), std::numeric_limits<double>::min())) + double(p) * std::log(n);
    }
    if (score < best_score) best_score = score, best = p;
  }
  return best;
}

void check_options(const ArRefitOptions& o) {
  const std::string where = "ar-refit options";
  if (o.min_order < 1 || o.min_order > o.max_order)
    throw input_error(where, "AR order", "the order range " + std::to_string(o.min_order) + ".." +
                                             std::to_string(o.max_order) + " is empty or starts at 0",
                      "Give 1 <= min_order <= max_order (HaTT uses 14..20)");
  if (o.segment_samples <= 2 * o.max_order)
    throw input_error(where, "segment length", "segments of " + std::to_string(o.segment_samples) +
                                                   " samples are too short for AR order " + std::to_string(o.max_order),
                      "Use segments longer than twice the order (1000 samples = 0.1 s by default)");
  if (o.cells_per_axis == 0 || o.min_segments == 0)
    throw input_error(where, "grouping", "cells_per_axis and min_segments must be at least 1", "Raise them");
}

void check_enough(const std::string& material, std::size_t pieces, const SegmentCut& cut, const ArRefitOptions& o) {
  if (cut.segments.size() >= o.min_segments) return;
  const std::string L = std::to_string(o.segment_samples);
  std::string what = std::to_string(pieces) + " train/val sections with " + std::to_string(cut.total_samples) +
                     " samples in all (the longest " + std::to_string(cut.longest_piece) + ") give " +
                     std::to_string(cut.segments.size()) + " usable segments of " + L + " samples";
  if (cut.silent + cut.at_rest > 0)
    what += " (" + std::to_string(cut.silent) + " silent and " + std::to_string(cut.at_rest) +
            " at-rest segments skipped)";
  what += "; the AR refit needs at least " + std::to_string(o.min_segments) + " segments, i.e. " +
          std::to_string(o.min_segments * o.segment_samples) + " samples of contact and motion in sections of at least " +
          L + " samples";
  throw input_error("material '" + material + "'", "AR refit", what,
                    "Record longer, give fewer sections to test and val when splitting, or use shorter segments");
}

std::vector<std::span<const double>> stretches(const std::vector<std::size_t>& members, const SegmentCut& cut,
                                               std::span<const TrainingPiece> pieces, std::size_t length) {
  std::vector<std::span<const double>> out;
  for (std::size_t m : members) {
    const LabelledSegment& s = cut.segments[m];
    out.push_back(pieces[s.piece].accel.subspan(s.start, length));
  }
  return out;
}

ar::ArModel fitted_model(const PooledBurg& fit, std::size_t p, const SegmentGroup& g, int number) {
  ar::ArModel m;
  m.number = number;
  m.ar_coeff = polynomial(fit, p);
  m.ar_lsf = ar::poly_to_lsf(m.ar_coeff);
  m.ma_coeff = {1.0};
  m.variance = variance(fit, p);
  m.speed = g.speed;
  m.force = g.force;
  return m;
}

// Header, maxima and the fitted models; poly_to_lsf refuses a model whose poles reach the unit
// circle (a perfectly periodic stretch): such a group is left out and its area goes to neighbours.
ar::ModelSet fitted_set(const std::string& material, const std::vector<SegmentGroup>& groups,
                        const std::vector<PooledBurg>& fits, std::size_t p, const SegmentCut& cut) {
  ar::ModelSet set;
  set.material = material;
  set.num_ar_coeff = int(p);
  for (const LabelledSegment& s : cut.segments) {
    set.max_speed = std::max(set.max_speed, s.speed);
    set.max_force = std::max(set.max_force, s.force);
  }
  for (std::size_t g = 0; g < groups.size(); ++g) {
    try {
      set.models.push_back(fitted_model(fits[g], p, groups[g], int(set.models.size()) + 1));
    } catch (const Error&) {
      continue;
    }
    set.speed_list.push_back(groups[g].speed);
    set.force_list.push_back(groups[g].force);
  }
  if (set.models.empty())
    throw failure("material '" + material + "': AR refit: every model's filter has a pole on the unit circle "
                  "(the acceleration is perfectly periodic); there is no noise to model");
  return set;
}

}  // namespace

ArRefit refit_piecewise_ar(const std::string& material, std::span<const TrainingPiece> pieces,
                           const ArRefitOptions& options) {
  check_options(options);
  const SegmentCut cut = cut_segments(pieces, options.segment_samples);
  check_enough(material, pieces.size(), cut, options);
  const auto groups = group_segments(cut.segments, options.cells_per_axis);
  std::vector<PooledBurg> fits;
  for (const SegmentGroup& g : groups)
    fits.push_back(pooled_burg(stretches(g.members, cut, pieces, options.segment_samples), options.max_order));
  ArRefit out;
  out.order = choose_order(fits, options);
  out.models = fitted_set(material, groups, fits, out.order, cut);
  out.fitted_models = out.models.models.size();
  out.segments = cut.segments.size();
  out.skipped_segments = cut.silent + cut.at_rest;
  out.models.source = "ar-refit of " + material + " (" + std::to_string(pieces.size()) + " train/val sections, " +
                      std::to_string(out.segments) + " segments of " + std::to_string(options.segment_samples) +
                      " samples, " + std::to_string(out.fitted_models) + " fitted models)";
  add_hatt_boundary_models(out.models);
  out.models.triangles = delaunay_triangles(out.models.speed_list, out.models.force_list);
  ar::PiecewiseArModel check(out.models);  // the renderer's own checks: a bug here, not bad input
  return out;
}

std::vector<std::vector<double>> render_repeats(const ar::PiecewiseArModel& model, std::span<const double> speed,
                                                std::span<const double> force, std::size_t repeats,
                                                std::uint64_t seed) {
  std::vector<std::vector<double>> out;
  for (std::size_t r = 0; r < repeats; ++r) out.push_back(ar::render_texture(model, speed, force, derive_seed(seed, r)));
  return out;
}

}  // namespace haptex::evaluate
