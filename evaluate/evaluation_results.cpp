#include "evaluate/evaluation_results.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace haptex::evaluate {
namespace {

template <typename Count>
std::size_t count_if(const Experiment& e, Count count) {
  std::size_t n = 0;
  for (const MaterialComparison& m : e.materials) n += count(m) ? 1 : 0;
  return n;
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

}  // namespace haptex::evaluate
