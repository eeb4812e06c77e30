#include "evaluate/baselines/ar_expectation.hpp"

#include <cmath>

#include "core/ar/expected_spectrum.hpp"
#include "core/ar/gaussian_noise.hpp"
#include "core/ar/texture_renderer.hpp"
#include "core/random_seeds.hpp"
#include "core/thread_clock.hpp"
#include "evaluate/inputs/section_signals.hpp"
#include "evaluate/measures/spectral_distance.hpp"

namespace haptex::evaluate {
namespace {

std::vector<std::size_t> shifted(const std::vector<std::size_t>& grid, std::size_t by) {
  std::vector<std::size_t> out;
  for (std::size_t t : grid) out.push_back(t + by);
  return out;
}

double mean_distance(const std::vector<std::vector<std::vector<double>>>& spectra, const std::vector<ArSection>& sections) {
  double sum = 0;
  std::size_t n = 0;
  for (std::size_t s = 0; s < sections.size(); ++s)
    for (std::size_t j = 0; j < sections[s].recorded.size(); ++j, ++n) sum += spectrum_distance(spectra[s][j], sections[s].recorded[j]);
  return n ? sum / double(n) : 0.0;
}

// The closed form against Monte Carlo, spectrum against spectrum: per window, the closed form's
// summed amplitude over Monte Carlo's, minus 1; the mean of its magnitude over the windows. Summing
// the 100 bins averages Monte Carlo's own sampling error (0.52 / sqrt(renders) per bin) down to
// about 0.7 % per window with 64 renders, and every window counts alike, so the quiet windows after a
// stroke stops (where the closed form misses the ringing filter) weigh as much as loud ones.
double spectrum_gap(const std::vector<std::vector<std::vector<double>>>& closed, const std::vector<std::vector<std::vector<double>>>& carlo) {
  double sum = 0;
  std::size_t n = 0;
  for (std::size_t s = 0; s < closed.size(); ++s)
    for (std::size_t j = 0; j < closed[s].size(); ++j, ++n) {
      double c = 0, m = 0;
      for (std::size_t k = 0; k < closed[s][j].size(); ++k) c += closed[s][j][k], m += carlo[s][j][k];
      sum += m > 0 ? std::fabs(c / m - 1) : (c > 0 ? 1.0 : 0.0);
    }
  return n ? sum / double(n) : 0.0;
}

// Mean window spectra of `renders` renderings of one section (plus sensor noise); the first `kept` kept.
std::vector<std::vector<double>> monte_carlo(const ar::PiecewiseArModel& model, const ArSection& s, const ArExpectationOptions& o,
                                             std::uint64_t seed, std::vector<std::vector<std::vector<double>>>& kept) {
  const std::vector<std::size_t> grid = shifted(s.grid, s.lead);
  std::vector<std::vector<double>> mean(grid.size(), std::vector<double>(100, 0.0));
  const double sigma = std::sqrt(o.noise_power);
  for (std::size_t r = 0; r < o.renders; ++r) {
    std::vector<double> x = ar::render_texture(model, s.speed, s.force, derive_seed(seed, r, 1));
    if (sigma > 0) {
      ar::GaussianNoise noise(derive_seed(seed, r, 2));
      for (double& v : x) v += sigma * noise.next();
    }
    auto spectra = grid_spectra(x, grid);
    for (std::size_t j = 0; j < grid.size(); ++j)
      for (std::size_t k = 0; k < 100; ++k) mean[j][k] += spectra[j][k] / double(o.renders);
    if (r < o.kept) kept.push_back(std::move(spectra));
  }
  return mean;
}

}  // namespace

ArSection held_start_section(const std::vector<double>& speed, const std::vector<double>& force, std::vector<std::size_t> grid,
                             std::vector<std::vector<double>> recorded) {
  ArSection s;
  s.lead = speed.empty() ? 0 : kArLeadSamples;
  s.speed.assign(s.lead, speed.empty() ? 0.0 : speed.front());
  s.force.assign(s.lead, force.empty() ? 0.0 : force.front());
  s.speed.insert(s.speed.end(), speed.begin(), speed.end());
  s.force.insert(s.force.end(), force.begin(), force.end());
  s.grid = std::move(grid);
  s.recorded = std::move(recorded);
  return s;
}

ArExpectation expected_ar_spectra(const ar::PiecewiseArModel& model, const std::vector<ArSection>& sections,
                                  const ArExpectationOptions& o) {
  ArExpectation e;
  std::vector<std::vector<std::vector<double>>> closed, carlo;
  ar::ExpectedSpectrumOptions cf;
  cf.noise_power = o.noise_power;
  for (std::size_t s = 0; s < sections.size(); ++s) {
    const double start = thread_seconds();
    closed.push_back(ar::expected_window_spectra(model, sections[s].speed, sections[s].force, shifted(sections[s].grid, sections[s].lead), cf));
    e.closed_form_seconds += thread_seconds() - start;
    e.closed_form_windows += sections[s].grid.size();
    if (o.renders == 0) continue;
    e.rendered_spectra.emplace_back();
    carlo.push_back(monte_carlo(model, sections[s], o, derive_seed(o.seed, s), e.rendered_spectra.back()));
  }
  e.closed_form = mean_distance(closed, sections);
  if (o.renders == 0) {
    e.method = "closed form";
    e.spectra = std::move(closed);
    return e;
  }
  e.monte_carlo = mean_distance(carlo, sections);
  double rendered = 0;
  for (std::size_t r = 0; r < o.kept && r < o.renders; ++r) {
    std::vector<std::vector<std::vector<double>>> one;
    for (const auto& section : e.rendered_spectra) one.push_back(section[r]);
    rendered += mean_distance(one, sections) / double(std::min(o.kept, o.renders));
  }
  e.rendered = rendered;
  e.gap = spectrum_gap(closed, carlo);
  const bool agree = e.gap <= o.agreement;
  e.method = agree ? "closed form" : "Monte Carlo";
  e.spectra = agree ? std::move(closed) : std::move(carlo);
  return e;
}

}  // namespace haptex::evaluate
