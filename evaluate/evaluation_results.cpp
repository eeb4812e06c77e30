#include "evaluate/evaluation_results.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "evaluate/measures/summary_statistics.hpp"

namespace haptex::evaluate {
namespace {

template <typename Count>
std::size_t count_if(const Experiment& e, Count count) {
  std::size_t n = 0;
  for (const MaterialComparison& m : e.materials) n += count(m) ? 1 : 0;
  return n;
}

// The finite values of figure(item), sorted, and their median; NaN when none is finite.
template <typename T, typename Figure>
double median_of(const std::vector<T>& v, Figure figure) {
  std::vector<double> values;
  for (const T& item : v)
    if (std::isfinite(figure(item))) values.push_back(figure(item));
  return values.empty() ? kNotMeasured : percentile(values, 50);
}

// Finite ratios model / floor, sorted.
std::vector<double> floor_ratios(const Experiment& e) {
  std::vector<double> r;
  for (const MaterialComparison& m : e.materials)
    if (std::isfinite(m.floor_ratio())) r.push_back(m.floor_ratio());
  std::sort(r.begin(), r.end());
  return r;
}

}  // namespace

std::size_t Experiment::better() const { return count_if(*this, [](const MaterialComparison& m) { return m.better(); }); }
std::size_t Experiment::significantly_better() const {
  return count_if(*this, [](const MaterialComparison& m) { return m.better() && m.significant(); });
}
std::size_t Experiment::significantly_worse() const {
  return count_if(*this, [](const MaterialComparison& m) { return !m.better() && m.significant(); });
}
double Experiment::mean_model() const {
  double s = 0;
  for (const MaterialComparison& m : materials) s += m.model;
  return materials.empty() ? 0 : s / double(materials.size());
}
double Experiment::mean_baseline() const {
  double s = 0;
  for (const MaterialComparison& m : materials) s += m.baseline;
  return materials.empty() ? 0 : s / double(materials.size());
}

std::size_t Experiment::within_floor(double margin) const {
  return count_if(*this, [margin](const MaterialComparison& m) { return m.floor_ratio() <= 1 + margin; });
}
std::size_t Experiment::below_floor() const {
  return count_if(*this, [](const MaterialComparison& m) { return m.below_floor; });
}
double Experiment::median_floor_ratio() const {
  const auto r = floor_ratios(*this);
  if (r.empty()) return kNotMeasured;
  return r.size() % 2 ? r[r.size() / 2] : (r[r.size() / 2 - 1] + r[r.size() / 2]) / 2;
}
double Experiment::worst_floor_ratio() const {
  const auto r = floor_ratios(*this);
  return r.empty() ? kNotMeasured : r.back();
}

Comparison comparison_of(std::string_view id) {
  const std::string_view base = id.substr(0, id.find(" ("));
  if (base.starts_with("stitched-")) return Comparison::stitched;
  if (base.ends_with("-vs-expected-ar")) return Comparison::expected_ar;
  if (base.ends_with("-vs-mean-spectrum")) return Comparison::mean_spectrum;
  return Comparison::rendered_ar;
}

std::string_view comparison_name(Comparison c) {
  switch (c) {
    case Comparison::expected_ar: return "expected-ar";
    case Comparison::mean_spectrum: return "mean-spectrum";
    case Comparison::stitched: return "stitched";
    case Comparison::rendered_ar: break;
  }
  return "rendered-ar";
}

std::size_t materials_with_floor(const Experiment& x) {
  return std::size_t(std::count_if(x.materials.begin(), x.materials.end(),
                                   [](const MaterialComparison& m) { return std::isfinite(m.floor_ratio()); }));
}

double closed_form_gap_percent(const MaterialFloor& f) { return 100 * f.closed_form_gap; }

double rendered_ratio(const MaterialFloor& f) { return f.rendered / f.distance; }

RealismMedians realism_medians(const Realism& r) {
  RealismMedians m;
  m.section_lsd_db = median_of(r.materials, [](const MaterialRealism& x) { return x.section_lsd_db; });
  m.spread_ratio = median_of(r.materials, [](const MaterialRealism& x) { return x.spread_ratio; });
  m.floor_ratio = median_of(r.materials, [](const MaterialRealism& x) { return x.floor_ratio; });
  m.rendered_floor_ratio = median_of(r.materials, [](const MaterialRealism& x) { return x.rendered_floor_ratio; });
  for (const MaterialRealism& x : r.materials) {
    m.materials += std::isfinite(x.spread_ratio);
    m.spread_in_range += x.spread_ratio >= kSpreadLow && x.spread_ratio <= kSpreadHigh;
    m.near_rendered_floor += x.rendered_floor_ratio <= kRenderedFloorMargin;
  }
  return m;
}

}  // namespace haptex::evaluate
