#include "evaluate/evaluation_results.hpp"

#include <numeric>

namespace haptex::evaluate {
namespace {

template <typename Count>
std::size_t count_if(const Experiment& e, Count count) {
  std::size_t n = 0;
  for (const MaterialComparison& m : e.materials) n += count(m) ? 1 : 0;
  return n;
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

}  // namespace haptex::evaluate
