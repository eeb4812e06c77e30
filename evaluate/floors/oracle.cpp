#include "evaluate/floors/oracle.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "convert/hatt_model_reader.hpp"
#include "core/ar/expected_spectrum.hpp"
#include "core/error.hpp"
#include "core/signal/spectrum.hpp"
#include "dataset/object_paths.hpp"
#include "dataset/window.hpp"
#include "evaluate/measures/summary_statistics.hpp"

namespace haptex::evaluate {
namespace {

constexpr std::size_t kGridPoints = 10;  // action points per window for the grid oracle, every 100 samples

// DFT321 keeps the summed power of the three axes: their noise adds as one channel of 3 sigma^2.
double dft321_noise_power(const dataset::Truth& truth) { return 3 * truth.accel_noise_m_s2 * truth.accel_noise_m_s2; }

const dataset::TruthRecording* find_recording(const dataset::MaterialTruth& t, const std::string& sha) {
  for (const dataset::TruthRecording& r : t.recordings)
    if (!sha.empty() && r.source_sha256 == sha) return &r;
  return nullptr;
}

// Where x falls on an axis extended by a silent 0 in front (extended index j is axis[j - 1]):
// the two neighbours and the weight of the upper one; held at both ends.
struct Neighbours {
  std::size_t lo = 0, hi = 0;
  double w = 0;
};
Neighbours locate(const std::vector<double>& axis, double x) {
  const std::size_t last = axis.size();
  if (!(x > 0)) return {0, 0, 0.0};
  if (x >= axis.back()) return {last, last, 0.0};
  const std::size_t hi = std::size_t(std::upper_bound(axis.begin(), axis.end(), x) - axis.begin()) + 1;
  const double lo_x = hi == 1 ? 0.0 : axis[hi - 2], hi_x = axis[hi - 1];
  return {hi - 1, hi, (x - lo_x) / (hi_x - lo_x)};
}

// Power of grid point (s, f) on the extended grid: index 0 is the silent row or column.
double extended_power(const dataset::TruthGrid& g, std::size_t s, std::size_t f, std::size_t k) {
  if (s == 0 || f == 0) return 0.0;
  const double a = g.spectrum(s - 1, f - 1)[k];
  return a * a;
}

// The grid's spectrum of each window, its power averaged over the oracle's ten points (one every 100
// samples from the 50th), each at the (speed, force) `action_at(t, sample)` gives for window t, plus
// the sensor's noise.
template <typename ActionAt>
std::vector<std::vector<double>> oracle_spectra(const dataset::TruthGrid& grid, const std::vector<std::size_t>& windows, double noise_power,
                                              ActionAt action_at) {
  std::vector<std::vector<double>> out;
  for (std::size_t t : windows) {
    std::vector<double> power(dataset::kTargetBins, 0.0);
    for (std::size_t p = 0; p < kGridPoints; ++p) {
      const auto [speed, force] = action_at(t, t + 50 + 100 * p);
      const auto at = grid_power_at(grid, speed, force);
      for (std::size_t k = 0; k < power.size(); ++k) power[k] += at[k] / double(kGridPoints);
    }
    for (double& v : power) v = std::sqrt(v);
    add_sensor_noise(power, noise_power);
    out.push_back(std::move(power));
  }
  return out;
}

std::vector<std::vector<double>> grid_section(const dataset::TruthGrid& grid, const dataset::TruthRecording& r, std::int64_t begin,
                                              const std::vector<std::size_t>& windows, double noise_power) {
  return oracle_spectra(grid, windows, noise_power, [&](std::size_t, std::size_t sample) {
    const std::size_t i = std::size_t(begin) + sample;
    return std::pair{double(r.speed_mm_s[i]), double(r.force_n[i])};
  });
}

// What the model's input tells of a window (docs/evaluate.md, "The input floor"): the recorded action up
// to the window's middle, where its action ends, and held there for the second half.
std::size_t known_action_sample(std::size_t t, std::size_t i) { return std::min(i, t + dataset::kActionEnd); }

// The grid's spectrum along that action, at the oracle's ten points.
std::vector<std::vector<double>> grid_input_section(const dataset::TruthGrid& grid, const SectionSignals& s,
                                                    const std::vector<std::size_t>& windows, double noise_power) {
  return oracle_spectra(grid, windows, noise_power, [&](std::size_t t, std::size_t sample) {
    const std::size_t i = known_action_sample(t, sample);
    return std::pair{double(s.speed[i]), double(s.force[i])};
  });
}

// The closed form along that action, one window at a time, blended every 100 samples as the grid's points.
std::vector<std::vector<double>> ar_input_section(const ar::PiecewiseArModel& model, const SectionSignals& s, double noise_power) {
  ar::ExpectedSpectrumOptions o;
  o.update = 100;
  o.noise_power = noise_power;
  std::vector<std::vector<double>> out;
  std::vector<double> speed(dataset::kWindowSamples), force(dataset::kWindowSamples);
  const std::size_t first[] = {0};
  for (std::size_t t : section_grid(s.accel.size())) {
    for (std::size_t i = 0; i < dataset::kWindowSamples; ++i) {
      speed[i] = s.speed[known_action_sample(t, t + i)];
      force[i] = s.force[known_action_sample(t, t + i)];
    }
    out.push_back(ar::expected_window_spectra(model, speed, force, first, o).front());
  }
  return out;
}

void check_length(const dataset::TruthRecording& r, const SectionSignals& s, const std::string& path, const std::string& material) {
  if (std::size_t(s.begin) + s.accel.size() > r.speed_mm_s.size())
    throw input_error(path, dataset::recording_path(material, r.index),
                      "the true action has " + std::to_string(r.speed_mm_s.size()) + " samples but the dataset's recording has at least " +
                          std::to_string(std::size_t(s.begin) + s.accel.size()),
                      "Give the truth.h5 written with the recordings this dataset was converted from");
}

ArSection true_action_section(const dataset::TruthRecording& r, const SectionSignals& s, std::vector<std::vector<double>> recorded) {
  ArSection a;
  a.lead = std::min<std::size_t>(std::size_t(s.begin), kArLeadSamples);
  const auto from = std::ptrdiff_t(std::size_t(s.begin) - a.lead), to = std::ptrdiff_t(std::size_t(s.begin) + s.accel.size());
  a.speed.assign(r.speed_mm_s.begin() + from, r.speed_mm_s.begin() + to);
  a.force.assign(r.force_n.begin() + from, r.force_n.begin() + to);
  a.grid = section_grid(s.accel.size());
  a.recorded = std::move(recorded);
  return a;
}

}  // namespace

bool beats_oracle(const std::vector<double>& model, const std::vector<double>& oracle) {
  if (model.size() != oracle.size())
    throw failure("beats_oracle: " + std::to_string(model.size()) + " model windows against " + std::to_string(oracle.size()) + " oracle windows");
  if (model.size() < 2) return false;
  std::vector<double> d;
  for (std::size_t j = 0; j < model.size(); ++j) d.push_back(model[j] - oracle[j]);
  const double independent = std::max(1.0, double(d.size()) / 10);
  return mean(d) < -3 * std::sqrt(sample_variance(d) / independent);
}

void add_sensor_noise(std::vector<double>& amplitude, double noise_power) {
  const double add = std::numbers::pi * noise_power / double(dataset::kWindowSamples);
  for (double& a : amplitude) a = std::sqrt(a * a + add);
}

std::vector<double> grid_power_at(const dataset::TruthGrid& grid, double speed, double force) {
  const Neighbours s = locate(grid.speeds_mm_s, speed), f = locate(grid.forces_n, force);
  std::vector<double> out(dataset::kTargetBins);
  for (std::size_t k = 0; k < out.size(); ++k)
    out[k] = (1 - s.w) * (1 - f.w) * extended_power(grid, s.lo, f.lo, k) + s.w * (1 - f.w) * extended_power(grid, s.hi, f.lo, k) +
             (1 - s.w) * f.w * extended_power(grid, s.lo, f.hi, k) + s.w * f.w * extended_power(grid, s.hi, f.hi, k);
  return out;
}

bool truth_knows_any(const dataset::Truth& truth, const std::vector<MaterialSignals>& signals) {
  for (const MaterialSignals& m : signals)
    if (const dataset::MaterialTruth* t = truth.find(m.id))
      for (const SectionSignals& s : m.test)
        if (find_recording(*t, s.source_sha256)) return true;
  return false;
}

std::optional<MaterialOracle> material_oracle(const dataset::Truth& truth, const std::string& truth_path, const MaterialSignals& m,
                                              const std::vector<std::vector<std::vector<double>>>& recorded, std::uint64_t seed) {
  const dataset::MaterialTruth* t = truth.find(m.id);
  if (!t) return std::nullopt;
  std::vector<const dataset::TruthRecording*> recordings;
  for (const SectionSignals& s : m.test) {
    const dataset::TruthRecording* r = find_recording(*t, s.source_sha256);
    if (!r) return std::nullopt;
    check_length(*r, s, truth_path, m.id);
    recordings.push_back(r);
  }
  MaterialOracle o;
  if (t->generator == "synth-material") {
    o.method = "truth grid";
    for (std::size_t s = 0; s < m.test.size(); ++s) {
      const std::vector<std::size_t> grid = section_grid(m.test[s].accel.size());
      o.spectra.push_back(grid_section(*t->grid, *recordings[s], m.test[s].begin, grid, dft321_noise_power(truth)));
      o.input_spectra.push_back(grid_input_section(*t->grid, m.test[s], grid, dft321_noise_power(truth)));
    }
    return o;
  }
  const ar::PiecewiseArModel model(convert::parse_hatt_model(t->model_xml, truth_path + ":/materials/" + m.id + "/@model_xml"));
  std::vector<ArSection> sections;
  for (std::size_t s = 0; s < m.test.size(); ++s) sections.push_back(true_action_section(*recordings[s], m.test[s], recorded[s]));
  ArExpectationOptions options;
  options.noise_power = dft321_noise_power(truth);
  options.seed = seed;
  o.ar = expected_ar_spectra(model, sections, options);
  o.method = o.ar->method;
  o.spectra = o.ar->spectra;
  for (const SectionSignals& s : m.test) o.input_spectra.push_back(ar_input_section(model, s, options.noise_power));
  return o;
}

}  // namespace haptex::evaluate
