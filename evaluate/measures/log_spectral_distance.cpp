#include "evaluate/measures/log_spectral_distance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.hpp"
#include "evaluate/measures/summary_statistics.hpp"

namespace haptex::evaluate {
namespace {

constexpr double kLowestFloor = 1e-9;  // m/s^2: keeps a silent training set from a zero floor
constexpr double kFloorPercentile = 5;

// Per bin over rows: the mean of the squared amplitudes (as an amplitude) and the coefficient of variation.
void column_statistics(const std::vector<std::vector<double>>& rows, std::vector<double>& rms, std::vector<double>& cv) {
  const std::size_t bins = rows.front().size();
  rms.assign(bins, 0.0), cv.assign(bins, 0.0);
  std::vector<double> column(rows.size());
  for (std::size_t k = 0; k < bins; ++k) {
    double power = 0;
    for (std::size_t j = 0; j < rows.size(); ++j) column[j] = rows[j][k], power += column[j] * column[j];
    rms[k] = std::sqrt(power / double(rows.size()));
    const double m = mean(column);
    cv[k] = m > 0 ? std::sqrt(sample_variance(column)) / m : std::numeric_limits<double>::quiet_NaN();
  }
}

}  // namespace

double log_spectral_distance(std::span<const double> a, std::span<const double> b, std::span<const double> floor) {
  if (a.size() != b.size() || a.size() != floor.size() || a.empty())
    throw failure("log-spectral distance: spectra of " + std::to_string(a.size()) + " and " + std::to_string(b.size()) +
                  " bins with a floor of " + std::to_string(floor.size()) + "; they must have the same, non-zero size");
  double sum = 0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (!(floor[k] > 0)) throw failure("log-spectral distance: the floor of bin " + std::to_string(k) + " is not positive");
    const double d = 20 * std::log10(std::max(a[k], floor[k]) / std::max(b[k], floor[k]));
    sum += d * d;
  }
  return std::sqrt(sum / double(a.size()));
}

std::vector<double> noise_floor(const std::vector<std::vector<double>>& windows) {
  if (windows.empty()) throw failure("noise floor: no training windows");
  std::vector<double> floor(windows.front().size()), column(windows.size());
  for (std::size_t k = 0; k < floor.size(); ++k) {
    for (std::size_t j = 0; j < windows.size(); ++j) column[j] = windows[j].at(k);
    floor[k] = std::max(kLowestFloor, percentile(column, kFloorPercentile));
  }
  return floor;
}

SectionRealism section_realism(const std::vector<std::vector<double>>& rendered, const std::vector<std::vector<double>>& recorded,
                               std::span<const double> floor) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  if (rendered.size() < 2 || rendered.size() != recorded.size()) return {nan, nan};
  std::vector<double> rms_r, cv_r, rms_t, cv_t;
  column_statistics(rendered, rms_r, cv_r);
  column_statistics(recorded, rms_t, cv_t);
  std::vector<double> ratios;
  for (std::size_t k = 0; k < cv_r.size(); ++k)
    if (std::isfinite(cv_r[k]) && std::isfinite(cv_t[k]) && cv_t[k] > 0) ratios.push_back(cv_r[k] / cv_t[k]);
  return {log_spectral_distance(rms_r, rms_t, floor), ratios.empty() ? nan : percentile(ratios, 50)};
}

}  // namespace haptex::evaluate
