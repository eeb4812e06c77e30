#include "evaluate/inputs/window_sets.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/error.hpp"
#include "core/signal/spectrum.hpp"
#include "dataset/window.hpp"

namespace haptex::evaluate {
namespace {

MeanAction mean_action(const SectionSignals& s, std::size_t t) {
  MeanAction p;
  for (std::size_t i = t; i < t + dataset::kWindowSamples; ++i) p.speed += s.speed[i], p.force += s.force[i];
  p.speed /= double(dataset::kWindowSamples), p.force /= double(dataset::kWindowSamples);
  return p;
}

double spread(const std::vector<MeanAction>& points, double MeanAction::*axis) {
  double m = 0, v = 0;
  for (const MeanAction& p : points) m += p.*axis;
  m /= double(points.size());
  for (const MeanAction& p : points) v += (p.*axis - m) * (p.*axis - m);
  const double sd = std::sqrt(v / double(points.size()));
  return sd > 0 ? sd : 1.0;  // a constant axis does not separate windows
}

}  // namespace

void WindowSet::append(const WindowSet& other) {
  spectra.insert(spectra.end(), other.spectra.begin(), other.spectra.end());
  actions.insert(actions.end(), other.actions.begin(), other.actions.end());
}

WindowSet section_windows(const SectionSignals& s) {
  return {grid_spectra(s.accel, section_grid(s.accel.size())), section_actions(s)};
}

std::vector<MeanAction> section_actions(const SectionSignals& s) {
  std::vector<MeanAction> actions;
  for (std::size_t t : section_grid(s.accel.size())) actions.push_back(mean_action(s, t));
  return actions;
}

WindowSet training_windows(const MaterialSignals& m) {
  WindowSet all;
  for (const SectionSignals& s : m.training) all.append(section_windows(s));
  return all;
}

std::vector<double> mean_spectrum(const WindowSet& w) {
  std::vector<double> sum(dataset::kTargetBins, 0.0);
  for (const auto& spectrum : w.spectra)
    for (std::size_t k = 0; k < sum.size(); ++k) sum[k] += spectrum[k];
  for (double& v : sum) v /= double(std::max<std::size_t>(1, w.spectra.size()));
  return sum;
}

std::vector<std::vector<double>> nearest_action_spectra(const WindowSet& training, const std::vector<MeanAction>& queries,
                                                        std::size_t k) {
  if (training.spectra.empty() || k == 0) throw failure("nearest_action_spectra: no training windows or k = 0");
  k = std::min(k, training.spectra.size());
  const double ds = spread(training.actions, &MeanAction::speed), df = spread(training.actions, &MeanAction::force);
  std::vector<std::size_t> order(training.actions.size());
  std::vector<double> d2(order.size());
  std::vector<std::vector<double>> out;
  for (const MeanAction& q : queries) {
    for (std::size_t i = 0; i < order.size(); ++i) {
      const double a = (training.actions[i].speed - q.speed) / ds, b = (training.actions[i].force - q.force) / df;
      d2[i] = a * a + b * b;
    }
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::partial_sort(order.begin(), order.begin() + std::ptrdiff_t(k), order.end(),
                      [&](std::size_t x, std::size_t y) { return d2[x] < d2[y] || (d2[x] == d2[y] && x < y); });
    std::vector<double> mean(training.spectra.front().size(), 0.0);
    for (std::size_t n = 0; n < k; ++n)
      for (std::size_t b = 0; b < mean.size(); ++b) mean[b] += training.spectra[order[n]][b] / double(k);
    out.push_back(std::move(mean));
  }
  return out;
}

}  // namespace haptex::evaluate
