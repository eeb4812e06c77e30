#pragma once
// What `haptex evaluate` found: per experiment and material, the model's and the baseline's spectral
// distances on the test sections with their comparison; the speed-vs-accuracy points; examples for
// the figures; the texture latents. evaluate/report_* turn it into report.md, results.json
// (schemas/results.schema.json), CSVs and charts.
#include <cstddef>
#include <limits>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "evaluate/measures/summary_statistics.hpp"
#include "evaluate/measures/welch_test.hpp"

namespace haptex::evaluate {

// One material in one experiment: per-window spectral distances (docs/architecture.md, "The model's sample") of the model
// and of the baseline on the same test windows.
inline constexpr double kNotMeasured = std::numeric_limits<double>::quiet_NaN();

struct MaterialComparison {
  std::string id, name;
  std::size_t windows = 0;
  double model = 0, baseline = 0;  // mean distance, m/s^2
  Quartiles difference;            // of baseline - model per window: > 0 where the model is closer
  WelchTest test;                  // model windows against baseline windows
  // The same windows scored in other ways (docs/evaluate.md, "Measures"):
  double model_lsd_db = kNotMeasured, baseline_lsd_db = kNotMeasured;  // mean log-spectral distance, dB
  double floor = kNotMeasured;          // the material's noise floor (Evaluation::floor_kind), mean distance
  double mean_spectrum = kNotMeasured;  // the material's mean training spectrum, mean distance
  bool below_floor = false;             // the model beats an oracle beyond sampling error: the oracle is wrong
  bool better() const { return model < baseline; }
  bool significant() const { return test.p < 0.05; }
  double floor_ratio() const { return model / floor; }
  double mean_spectrum_ratio() const { return model / mean_spectrum; }
};

struct Experiment {
  std::string id;           // per-material | unified-new-actions | unified-new-presses | stitched-<method> | external-<name> | stitched-external-<name>
  std::string title;        // what it tests, in the paper's words
  std::string model_label;  // e.g. "unified (model.h5)"
  std::string baseline_label;
  std::vector<MaterialComparison> materials;

  std::size_t better() const;
  std::size_t significantly_better() const;
  std::size_t significantly_worse() const;
  double mean_model() const;
  double mean_baseline() const;
  // Against the noise floor: materials whose model distance is within `margin` (0.1: 10 %) of the
  // floor's; the median and largest ratio model / floor (NaN without a floor); oracles beaten.
  std::size_t within_floor(double margin) const;
  double median_floor_ratio() const;
  double worst_floor_ratio() const;
  std::size_t below_floor() const;
};

// One point of the speed-vs-accuracy chart.
struct SpeedPoint {
  std::string method, setting;
  double seconds_per_second = 0;  // compute time per second of rendered vibration, one core
  double distance = 0;            // mean spectral distance over the test windows, m/s^2
  std::string kind = "spectrum";  // "spectrum" (predicts spectra) or "signal" (renders vibration)
  // Signals only (NaN for spectra): the medians over materials of the realism figures (Realism).
  double section_lsd_db = kNotMeasured, spread_ratio = kNotMeasured;
};

// How real a rendered signal looks next to the recording, per material (mean over its test sections;
// docs/evaluate.md, "Realism"): the log-spectral distance (dB) of the section-average power spectrum,
// and the median over bins of the coefficient of variation of window amplitudes, divided by the
// recording's (1: as steady as the recording; < 1 too steady; > 1 too wild).
struct MaterialRealism {
  std::string id, name;
  double section_lsd_db = kNotMeasured, spread_ratio = kNotMeasured;
  // The rendering's mean window distance to the recording, over the oracle's, and over the
  // generating model's own renderings' (AR oracles): the best a rendering that varies like the
  // surface can score is the latter, about sqrt(2) times the oracle (docs/evaluate.md, "Realism").
  double distance = kNotMeasured, floor_ratio = kNotMeasured, rendered_floor_ratio = kNotMeasured;
};
struct Realism {
  std::string method, setting;
  std::vector<MaterialRealism> materials;
};

// The best any predictor can score on a material's test windows (docs/evaluate.md, "The noise floor").
struct MaterialFloor {
  std::string id, name;
  std::string kind;    // "oracle" (the generating process is known) or "estimate"
  std::string method;  // oracle: "closed form", "Monte Carlo" or "truth grid"; estimate: "k nearest training windows"
  std::size_t windows = 0;
  double distance = kNotMeasured, lsd_db = kNotMeasured;  // the floor's mean distances to the recording
  double closed_form = kNotMeasured, monte_carlo = kNotMeasured;  // AR oracles: the distance of each way
  double rendered = kNotMeasured;  // AR oracles: the generating model rendered (mean over renders)
  double estimate = kNotMeasured;  // the empirical estimate's distance, beside an oracle to check it
  double baseline_expected = kNotMeasured;  // the AR baseline's expected spectrum at the recorded action
  double closed_form_gap = kNotMeasured;    // AR oracles: how far the two ways' spectra differ (ArExpectation::gap)
  double input_floor = kNotMeasured;  // oracles: the generating process given only the model's input (MaterialOracle)
};

// Figure 5: one test window of a material: frequencies 10..1000 Hz with true, model and baseline
// spectra; and the first samples of its test section: true, stitched model and baseline signals.
struct NamedSeries {
  std::string name;
  std::vector<double> values;
};
struct Example {
  std::string id, name;
  std::vector<double> truth_spectrum, model_spectrum, baseline_spectrum;
  std::vector<double> truth_signal, model_signal, baseline_signal;  // 10 kHz
  // The predictions files' (--predictions) spectrum of the same window and, where they have them,
  // their signal of the same section; named by the files' names (CSV columns `external-NAME`).
  std::vector<NamedSeries> external_spectra, external_signals;
};

// What report.html plays and shows of a material (docs/evaluate.md, "report.html"): its test sections
// in order, joined by kClipFadeSamples cross-fades, up to kClipSamples, as recorded, as the stitched
// model signal and as the AR baseline rendered it (10 kHz); the three spectra of the first section's
// middle window; and its first test press's peak image (PNG, at most kClipImageWidth pixels wide;
// empty where it has none).
inline constexpr std::size_t kClipSamples = 30000;     // 3 s
inline constexpr std::size_t kClipFadeSamples = 50;    // 5 ms
inline constexpr int kClipImageWidth = 320;
struct MaterialClip {
  std::string id, name;
  std::vector<double> recorded, model, baseline;
  std::vector<double> recorded_spectrum, model_spectrum, baseline_spectrum;
  std::vector<std::uint8_t> press_png;
  std::size_t sections = 0;  // test sections the clips join
};

// The texture map: 2-D PCA of the unified model's latents.
struct LatentPoint {
  std::string id, name, kind;  // kind: "training" (the material's mean training latent) or "test press"
  double x = 0, y = 0;
};

struct InputFile {
  std::string path, sha256;
};

// A predictions file of a model trained elsewhere (docs/benchmark.md), as the report names it.
struct PredictionsFile {
  std::string name, path, sha256, source;  // source: the file's own account of how it was made
};

struct Evaluation {
  InputFile dataset, split;
  std::vector<InputFile> models;
  std::vector<PredictionsFile> predictions;
  std::string baseline, reconstruct;  // options as given
  std::size_t repeats = 0;            // baseline renderings per test section
  std::vector<Experiment> experiments;
  std::vector<SpeedPoint> speed;
  std::vector<Example> examples;
  std::vector<MaterialClip> clips;  // every material with a stitched signal
  std::vector<LatentPoint> latents;
  std::string floor_kind;  // "oracle" (--truth) or "estimate"; see MaterialFloor
  std::vector<MaterialFloor> floors;
  std::vector<Realism> realism;
  std::vector<std::string> notes;  // what was skipped and why
  double seconds = 0;              // wall-clock time of the evaluation
};

// --- Figures derived from an evaluation, the same for every writer and for the speed points -------

// Which question an experiment answers, by its id without the " (model label)" suffix
// (docs/evaluate.md, "Which comparison answers which question"):
// - rendered_ar: predicted spectra against the AR baseline rendered (per-material, unified-new-*: the paper's protocol);
// - expected_ar: predicted spectra against the AR baseline's expected spectrum (*-vs-expected-ar: like for like);
// - mean_spectrum: predicted spectra against each material's mean training spectrum (*-vs-mean-spectrum);
// - stitched: the stitched signal against the AR baseline rendered (stitched-*: signal against signal).
enum class Comparison { rendered_ar, expected_ar, mean_spectrum, stitched };
Comparison comparison_of(std::string_view experiment_id);
std::string_view comparison_name(Comparison c);  // "rendered-ar", "expected-ar", "mean-spectrum", "stitched"

// Materials whose model / floor ratio is a number (the floor was measured).
std::size_t materials_with_floor(const Experiment& x);

// An AR oracle's two ways apart: MaterialFloor::closed_form_gap in percent; NaN when not measured.
double closed_form_gap_percent(const MaterialFloor& f);
// The generating model rendered against the floor: rendered / distance (well above 1: it pays the
// texture's randomness twice); NaN without both.
double rendered_ratio(const MaterialFloor& f);

// The medians over materials of a rendering's realism figures, each over the materials where it was
// measured (NaN where none was); materials: how many have a spread ratio.
struct RealismMedians {
  double section_lsd_db = kNotMeasured, spread_ratio = kNotMeasured;
  double floor_ratio = kNotMeasured, rendered_floor_ratio = kNotMeasured;
  std::size_t materials = 0;
  std::size_t spread_in_range = 0;        // materials with a spread ratio in [kSpreadLow, kSpreadHigh]
  std::size_t near_rendered_floor = 0;    // materials within kRenderedFloorMargin of the rendered floor
};
// What "varies like the surface" and "scores like the best rendering" mean in the counts above.
inline constexpr double kSpreadLow = 0.8, kSpreadHigh = 1.2, kRenderedFloorMargin = 1.25;
RealismMedians realism_medians(const Realism& r);

}  // namespace haptex::evaluate
