#pragma once
// What `haptex evaluate` found: per experiment and material, the model's and the baseline's spectral
// distances on the test sections with their comparison; the speed-vs-accuracy points; examples for
// the figures; the texture latents. evaluate/report_* turn it into report.md, results.json
// (schemas/results.schema.json), CSVs and charts.
#include <cstddef>
#include <string>
#include <vector>

#include "evaluate/summary_statistics.hpp"
#include "evaluate/welch_test.hpp"

namespace haptex::evaluate {

// One material in one experiment: per-window spectral distances (DESIGN.md section 3) of the model
// and of the baseline on the same test windows.
struct MaterialComparison {
  std::string id, name;
  std::size_t windows = 0;
  double model = 0, baseline = 0;  // mean distance, m/s^2
  Quartiles difference;            // of baseline - model per window: > 0 where the model is closer
  WelchTest test;                  // model windows against baseline windows
  bool better() const { return model < baseline; }
  bool significant() const { return test.p < 0.05; }
};

struct Experiment {
  std::string id;           // per-material | unified-new-actions | unified-new-presses | stitched-<method>
  std::string title;        // what it tests, in the paper's words
  std::string model_label;  // e.g. "unified (model.h5)"
  std::string baseline_label;
  std::vector<MaterialComparison> materials;

  std::size_t better() const;
  std::size_t significantly_better() const;
  std::size_t significantly_worse() const;
  double mean_model() const;
  double mean_baseline() const;
};

// One point of the speed-vs-accuracy chart.
struct SpeedPoint {
  std::string method, setting;
  double seconds_per_second = 0;  // compute time per second of rendered vibration, one core
  double distance = 0;            // mean spectral distance over the test windows, m/s^2
};

// Figure 5: one test window of a material: frequencies 10..1000 Hz with true, model and baseline
// spectra; and the first samples of its test section: true, stitched model and baseline signals.
struct Example {
  std::string id, name;
  std::vector<double> truth_spectrum, model_spectrum, baseline_spectrum;
  std::vector<double> truth_signal, model_signal, baseline_signal;  // 10 kHz
};

// The texture map: 2-D PCA of the unified model's latents.
struct LatentPoint {
  std::string id, name, kind;  // kind: "training" (the material's mean training latent) or "test press"
  double x = 0, y = 0;
};

struct InputFile {
  std::string path, sha256;
};

struct Evaluation {
  InputFile dataset, split;
  std::vector<InputFile> models;
  std::string baseline, reconstruct;  // options as given
  std::size_t repeats = 0;            // baseline renderings per test section
  std::vector<Experiment> experiments;
  std::vector<SpeedPoint> speed;
  std::vector<Example> examples;
  std::vector<LatentPoint> latents;
  std::vector<std::string> notes;  // what was skipped and why
  double seconds = 0;              // wall-clock time of the evaluation
};

}  // namespace haptex::evaluate
