#pragma once
// `haptex evaluate`: the learned models against an AR baseline on every material's test sections
// (Heravi et al. 2020, section V), in the spectral domain and as stitched time signals, with the
// compute time of every method for the speed-vs-accuracy chart.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/progress.hpp"
#include "evaluate/inputs/external_predictions.hpp"
#include "evaluate/evaluation_results.hpp"
#include "predict/model.hpp"
#include "render/reconstruction.hpp"
#include "split/split_windows.hpp"

namespace haptex::evaluate {

enum class Baseline { ar_refit, hatt_published };

struct EvaluationOptions {
  Baseline baseline = Baseline::ar_refit;
  std::string hatt_models;                              // directory of Models_<Material>.xml (hatt-published)
  // The stitched-signal experiment's method; none (--reconstruct none): no such experiment.
  std::optional<render::Reconstruction> reconstruct = render::Reconstruction::fgla;
  std::size_t repeats = 10;                             // baseline renderings (seeds) per test section
  // Speed-vs-accuracy and realism points; the largest is the experiment's. 4 iterations leave a signal about as varied
  // as the surface (docs/evaluate.md, "Realism").
  std::vector<std::size_t> fgla_iterations{0, 4, 8, 32, 100};
  std::string truth;               // truth.h5 of haptex synth (hatt or materials): the oracle noise floor; empty: estimates
  std::uint64_t seed = 0;
  unsigned threads = 0;
  std::vector<PredictionsInput> predictions;  // --predictions NAME=FILE: models trained elsewhere (docs/benchmark.md)
};

struct ModelInput {
  std::string path, label;  // label: how the report names it
  predict::Model model;
};

// Throws haptex::Error (bad_input) when there is neither a model nor predictions; when a model was
// trained on another dataset or split (hashes), or does not know a material of the split; as
// read_external_predictions throws, or when two predictions share a name; as dataset::read_truth_file throws; and as the baselines throw (a material whose training
// sections are too short for the AR fit; no published model for a material).
Evaluation run_evaluation(const split::DatasetSplit& split, const std::vector<ModelInput>& models,
                          const EvaluationOptions& options, const Progress& progress = {});

}  // namespace haptex::evaluate
