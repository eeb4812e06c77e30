#pragma once
// Measures beside the paper's Euclidean distance (docs/evaluate.md, "Measures"). The Euclidean
// distance in m/s^2 is ruled by a material's loudest bins and by its loudest materials; these see
// quiet bins and quiet materials too, and whether a rendered signal varies like a real texture.
#include <span>
#include <vector>

namespace haptex::evaluate {

// Log-spectral distance in dB of two amplitude spectra: sqrt(mean_k (20 log10(max(a_k, f_k) /
// max(b_k, f_k)))^2), where f is the noise floor per bin (noise_floor below), so bins that are
// silent in both spectra count as equal instead of exploding. Throws haptex::Error when the sizes
// differ or a floor value is not positive.
double log_spectral_distance(std::span<const double> a, std::span<const double> b, std::span<const double> floor);

// A material's noise level per bin: the 5th percentile of the bin's amplitude over its training
// windows (the quietest windows hold little but the sensor and the filters' rings), and never
// below 1e-9 m/s^2. windows: rows of amplitude spectra of one size. Throws haptex::Error when empty.
std::vector<double> noise_floor(const std::vector<std::vector<double>>& windows);

// Realism of one rendered section against the recording over the same windows (rows of amplitude
// spectra, one per window):
// - section_lsd_db: log_spectral_distance of the two section-average power spectra (as amplitudes);
// - spread_ratio: per bin, the coefficient of variation (sample standard deviation / mean) of the
//   window amplitudes, rendered over recorded; the median over the bins. Noise-like texture at a
//   steady action has a Rayleigh coefficient of about 0.52: a ratio below 1 is steadier than the
//   recording, above 1 wilder.
// NaN for both when there are fewer than 2 windows.
struct SectionRealism {
  double section_lsd_db, spread_ratio;
};
SectionRealism section_realism(const std::vector<std::vector<double>>& rendered, const std::vector<std::vector<double>>& recorded,
                               std::span<const double> floor);

}  // namespace haptex::evaluate
