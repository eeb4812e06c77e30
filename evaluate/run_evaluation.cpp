#include "dataset/object_paths.hpp"
#include "evaluate/run_evaluation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <compare>
#include <map>
#include <mutex>
#include <optional>
#include <span>

#include <Eigen/SVD>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "core/random_seeds.hpp"
#include "core/sha256.hpp"
#include "core/signal/crossfade.hpp"
#include "core/thread_clock.hpp"
#include "dataset/format.hpp"
#include "dataset/press_images.hpp"
#include "dataset/window.hpp"
#include "evaluate/baselines/ar_expectation.hpp"
#include "evaluate/baselines/ar_refit.hpp"
#include "evaluate/baselines/hatt_published.hpp"
#include "evaluate/measures/log_spectral_distance.hpp"
#include "evaluate/floors/oracle.hpp"
#include "evaluate/inputs/section_signals.hpp"
#include "evaluate/measures/spectral_distance.hpp"
#include "evaluate/inputs/window_sets.hpp"
#include "predict/predictor.hpp"
#include "predict/training_data.hpp"
#include "render/griffin_lim.hpp"
#include "render/online_reconstruction.hpp"
#include "render/shaped_noise.hpp"

namespace haptex::evaluate {
namespace {

constexpr std::size_t kExampleSamples = 2000;

// Per-window distances of one method, what computing it cost, and for signals how real they look.
struct Scores {
  std::vector<double> windows, lsd;    // Euclidean distance (m/s^2) and log-spectral distance (dB) per window
  double seconds = 0, rendered_seconds = 0;
  std::vector<SectionRealism> realism;  // time-domain methods: one per test section
  void add(const Scores& o) {
    windows.insert(windows.end(), o.windows.begin(), o.windows.end());
    lsd.insert(lsd.end(), o.lsd.begin(), o.lsd.end());
    realism.insert(realism.end(), o.realism.begin(), o.realism.end());
    seconds += o.seconds, rendered_seconds += o.rendered_seconds;
  }
};

// A method scored on the test windows: a model in one experiment, the stitched spectra turned into
// vibration by one reconstruction, or a reference the models are read against.
struct MethodKey {
  enum class Kind {
    per_material, unified_new_actions, unified_new_presses,  // `model`: which of the models
    stitched,                                                 // `reconstruction`; fgla: `iterations`
    mean_spectrum, expected_ar, floor, input_floor, floor_estimate, oracle_rendered,
    external, external_signal,  // `model`: which of the predictions files (docs/benchmark.md)
  };
  Kind kind;
  std::size_t model = 0;
  render::Reconstruction reconstruction = render::Reconstruction::fgla;
  std::size_t iterations = 0;

  // Kind, then model: the order the speed chart lists the models' points in.
  auto operator<=>(const MethodKey&) const = default;
  bool is_model() const { return kind <= Kind::unified_new_presses; }  // the first three kinds
  bool is_external() const { return kind == Kind::external || kind == Kind::external_signal; }
};
using Kind = MethodKey::Kind;

// How experiment ids and the speed chart name a model's experiment.
std::string model_kind_name(Kind kind) {
  return kind == Kind::per_material ? "per-material" : kind == Kind::unified_new_actions ? "unified-new-actions" : "unified-new-presses";
}

// The stitched spectra turned into vibration by `reconstruction` (fgla: with `iterations`).
MethodKey reconstruction_key(render::Reconstruction reconstruction, std::size_t iterations = 0) {
  return {.kind = Kind::stitched, .reconstruction = reconstruction, .iterations = iterations};
}

struct MaterialRun {
  Scores baseline;
  std::map<MethodKey, Scores> methods;
  MaterialFloor floor;
  Example example;
  MaterialClip clip;
};

// The codes one unified model gives a material: its training latent mean and each test press.
struct Codes {
  predict::TextureCode training;
  std::vector<predict::TextureCode> test_presses;
};

// Both distances of predicted spectra to the recording's, window by window.
Scores score(const std::vector<std::vector<double>>& predicted, const std::vector<std::vector<double>>& truth, const std::vector<double>& floor) {
  Scores s;
  for (std::size_t j = 0; j < truth.size(); ++j) {
    s.windows.push_back(spectrum_distance(predicted[j], truth[j]));
    s.lsd.push_back(log_spectral_distance(predicted[j], truth[j], floor));
  }
  return s;
}

// The mean of several scorings of the same windows (renderings, presses), window by window; their
// costs add up; realism, where they have it, is averaged per section.
Scores average(const std::vector<Scores>& each) {
  Scores out = each.front();
  for (std::size_t r = 1; r < each.size(); ++r) {
    for (std::size_t j = 0; j < out.windows.size(); ++j) out.windows[j] += each[r].windows[j], out.lsd[j] += each[r].lsd[j];
    out.seconds += each[r].seconds, out.rendered_seconds += each[r].rendered_seconds;
  }
  for (std::size_t j = 0; j < out.windows.size(); ++j) out.windows[j] /= double(each.size()), out.lsd[j] /= double(each.size());
  for (std::size_t k = 0; k < out.realism.size(); ++k) {
    SectionRealism& mean_realism = out.realism[k];
    mean_realism = {0, 0};
    for (const Scores& s : each) {
      mean_realism.section_lsd_db += s.realism[k].section_lsd_db / double(each.size());
      mean_realism.spread_ratio += s.realism[k].spread_ratio / double(each.size());
    }
  }
  return out;
}

// A rendered signal's scores on one section: both distances and its realism.
Scores signal_scores(const std::vector<std::vector<double>>& spectra, const std::vector<std::vector<double>>& truth, const std::vector<double>& floor) {
  Scores s = score(spectra, truth, floor);
  s.realism.push_back(section_realism(spectra, truth, floor));
  return s;
}

ar::PiecewiseArModel baseline_model(const MaterialSignals& m, const EvaluationOptions& o) {
  if (o.baseline == Baseline::hatt_published) return load_hatt_published(o.hatt_models, m.name);
  const std::vector<TrainingPiece> pieces = m.pieces();
  return ar::PiecewiseArModel(refit_piecewise_ar(m.name, pieces).models);
}

// The model's spectra for every grid window, one single query at a time as a haptic loop asks.
Scores predict_scores(predict::Predictor& p, const predict::TextureCode& code, const Eigen::MatrixXf& actions,
                      const std::vector<std::vector<double>>& truth, const std::vector<double>& floor,
                      std::vector<std::vector<double>>* spectra) {
  std::vector<std::vector<double>> predicted(truth.size(), std::vector<double>(dataset::kTargetBins));
  std::vector<float> out(dataset::kTargetBins);
  const double start = thread_seconds();
  for (std::size_t j = 0; j < truth.size(); ++j) {
    p.predict(code, std::span<const float>(actions.col(Eigen::Index(j)).data(), dataset::kActionValues), out);
    std::copy(out.begin(), out.end(), predicted[j].begin());
  }
  const double seconds = thread_seconds() - start;
  Scores s = score(predicted, truth, floor);
  s.seconds = seconds;
  s.rendered_seconds = double(truth.size()) * double(dataset::kGridStride) / dataset::kSampleRateHz;  // each prediction covers the next hop
  if (spectra) *spectra = std::move(predicted);
  return s;
}

render::MagnitudeFrames frames_of(const std::vector<std::vector<double>>& spectra) {
  std::vector<double> flat;
  for (const auto& s : spectra) flat.insert(flat.end(), s.begin(), s.end());
  return render::target_magnitudes(std::span<const double>(flat));
}

std::vector<double> online_signal(const render::MagnitudeFrames& frames, std::size_t length, std::uint64_t seed) {
  render::OnlineReconstruction online({.scatter = true, .seed = seed});
  return render::stream_frames(online, frames, length);
}

// The stitched signal of the predicted spectra, scored on the same windows (offset grid[0] = frame 0).
static_assert(dataset::kGridStride == render::kReconstructionHop, "stitching takes grid window m as reconstruction frame m");
Scores stitched_scores(const std::vector<std::vector<double>>& spectra, const std::vector<std::size_t>& grid,
                       const std::vector<std::vector<double>>& truth, const std::vector<double>& floor, double predict_seconds,
                       const MethodKey& key, std::uint64_t seed, std::vector<double>* signal) {
  const render::MagnitudeFrames frames = frames_of(spectra);
  const std::size_t length = render::covered_samples(frames.frames);
  const double start = thread_seconds();
  using render::Reconstruction;
  std::vector<double> x = key.reconstruction == Reconstruction::online  ? online_signal(frames, length, seed)
                         : key.reconstruction == Reconstruction::noise ? render::shaped_noise(frames, length, {seed})
                                                                       : render::griffin_lim(frames, length, {key.iterations, 0.99, render::InitialPhase::random, seed});
  const double seconds = thread_seconds() - start + predict_seconds;
  std::vector<std::size_t> local;
  for (std::size_t t : grid) local.push_back(t - grid[0]);
  Scores s = signal_scores(grid_spectra(x, local), truth, floor);
  s.seconds = seconds;
  s.rendered_seconds = double(spectra.size()) * double(dataset::kGridStride) / dataset::kSampleRateHz;
  if (signal) *signal = std::move(x);
  return s;
}

// A predictions file's spectra of one section's windows (rows [row, row + grid size)) and, when it
// has them, its signal of the section (grid section `k`), as the built-in models are scored.
void score_external(MaterialRun& run, std::size_t i, const ExternalPredictions& p, std::size_t row, std::size_t k,
                    const std::vector<std::size_t>& grid, const std::vector<std::vector<double>>& truth, const std::vector<double>& floor) {
  const double rendered_seconds = double(grid.size()) * double(dataset::kGridStride) / dataset::kSampleRateHz;  // as the models'
  const auto first = p.spectra.begin() + std::ptrdiff_t(row);
  Scores spectra = score({first, first + std::ptrdiff_t(grid.size())}, truth, floor);
  spectra.seconds = p.query_seconds * double(grid.size()), spectra.rendered_seconds = rendered_seconds;
  run.methods[{Kind::external, i}].add(spectra);
  if (p.signals.empty()) return;
  Scores signal = signal_scores(grid_spectra(p.signals[k], grid), truth, floor);
  signal.seconds = p.signal_seconds * double(grid.size()) / double(p.spectra.size());  // the file's total, shared by windows
  signal.rendered_seconds = rendered_seconds;
  run.methods[{Kind::external_signal, i}].add(signal);
}

std::vector<double> head(const std::vector<double>& v, std::size_t from, std::size_t samples = kExampleSamples) {
  const std::size_t end = std::min(v.size(), from + samples);
  return from < end ? std::vector<double>(v.begin() + std::ptrdiff_t(from), v.begin() + std::ptrdiff_t(end)) : std::vector<double>{};
}

// report.html's clip runs on over a material's test sections, in order, up to kClipSamples; the three
// signals take the same length from each section, so they stay aligned.
void extend_clip(MaterialClip& clip, const std::vector<double>& recorded, const std::vector<double>& model,
                 const std::vector<double>& baseline) {
  const std::size_t overlap = std::min(kClipFadeSamples, clip.recorded.size());
  if (clip.recorded.size() >= kClipSamples) return;
  const std::size_t n = std::min({recorded.size(), model.size(), baseline.size(), kClipSamples - clip.recorded.size() + overlap});
  for (const auto& [to, from] : {std::pair{&clip.recorded, &recorded}, {&clip.model, &model}, {&clip.baseline, &baseline}})
    signal::append_crossfaded(*to, std::span(*from).first(n), kClipFadeSamples);
  clip.sections += n > overlap;
}

struct Context {
  const std::vector<ModelInput>& models;
  const std::vector<ExternalPredictions>& external;
  std::vector<std::size_t> first_row, first_section;  // per material: its first window and section in the grid
  const std::vector<std::vector<Codes>>& codes;  // [model][material]; empty for per-material models
  const EvaluationOptions& options;
  const std::optional<dataset::Truth>& truth;  // --truth: the oracle where it knows a material
  std::vector<MethodKey> stitched_keys;    // every reconstruction scored (speed-vs-accuracy points)
  std::optional<MethodKey> stitched_key;   // the one the stitched-signal experiment reports
  int stitched_model = -1;                 // the first unified model, whose new-press spectra are stitched
};

// What a material's training windows give every method: the recording's noise level per bin (the
// log-spectral distance's floor), the mean spectrum (the best action-blind predictor) and the
// windows themselves (the empirical floor estimate).
struct MaterialReferences {
  WindowSet training;
  std::vector<double> noise, mean;
};

MaterialReferences material_references(const MaterialSignals& signals) {
  MaterialReferences r{training_windows(signals), {}, {}};
  if (r.training.spectra.empty())
    throw Error(Error::Kind::bad_input, "evaluate: material '" + signals.id + "' has no training window; give it longer sections");
  r.noise = noise_floor(r.training.spectra);
  r.mean = mean_spectrum(r.training);
  return r;
}

// The AR baseline rendered `repeats` times along the recorded action (the paper's protocol).
Scores rendered_baseline(const ar::PiecewiseArModel& baseline, const SectionSignals& section, const std::vector<std::size_t>& grid,
                         const std::vector<std::vector<double>>& truth, const std::vector<double>& floor, const Context& c,
                         std::uint64_t seed, std::vector<double>& first_render, std::vector<std::vector<double>>& first_spectra) {
  const double start = thread_seconds();
  auto renders = render_repeats(baseline, section.speed, section.force, c.options.repeats, seed);
  const double seconds = thread_seconds() - start;
  std::vector<Scores> each;
  for (std::size_t r = 0; r < renders.size(); ++r) {
    const auto spectra = grid_spectra(renders[r], grid);
    each.push_back(signal_scores(spectra, truth, floor));
    if (r == 0) first_spectra = spectra;
  }
  first_render = std::move(renders.front());
  Scores s = average(each);
  s.seconds = seconds;
  s.rendered_seconds = double(c.options.repeats * section.accel.size()) / dataset::kSampleRateHz;
  return s;
}

// Per test section: the oracle's spectra (or, without one, the k-nearest estimate's), and for an
// AR oracle its renderings (scored each, then averaged).
void score_floor(MaterialRun& run, std::size_t m, const MaterialSignals& signals, const MaterialReferences& ref,
                 const std::vector<std::vector<std::vector<double>>>& recorded, const Context& c) {
  MaterialFloor& f = run.floor;
  f = {signals.id, signals.name, "estimate", "k nearest training windows"};
  std::optional<MaterialOracle> oracle;
  if (c.truth) oracle = material_oracle(*c.truth, c.options.truth, signals, recorded, derive_seed(c.options.seed, 11, m));
  for (std::size_t s = 0; s < signals.test.size(); ++s) {
    if (recorded[s].empty()) continue;
    const auto estimate = nearest_action_spectra(ref.training, section_actions(signals.test[s]), kNearestWindows);
    run.methods[{Kind::floor_estimate}].add(score(estimate, recorded[s], ref.noise));
    if (!oracle) continue;
    run.methods[{Kind::floor}].add(score(oracle->spectra[s], recorded[s], ref.noise));
    run.methods[{Kind::input_floor}].add(score(oracle->input_spectra[s], recorded[s], ref.noise));
    if (!oracle->ar) continue;
    std::vector<Scores> each;
    for (const auto& rendering : oracle->ar->rendered_spectra[s]) each.push_back(signal_scores(rendering, recorded[s], ref.noise));
    run.methods[{Kind::oracle_rendered}].add(average(each));
  }
  f.estimate = mean(run.methods[{Kind::floor_estimate}].windows);
  if (!oracle) {
    run.methods[{Kind::floor}] = run.methods[{Kind::floor_estimate}];
  } else {
    f.kind = "oracle", f.method = oracle->method;
    f.input_floor = mean(run.methods[{Kind::input_floor}].windows);
    if (oracle->ar)
      f.closed_form = oracle->ar->closed_form, f.monte_carlo = oracle->ar->monte_carlo, f.closed_form_gap = oracle->ar->gap,
      f.rendered = oracle->ar->rendered;
  }
  const Scores& floor = run.methods[{Kind::floor}];
  f.windows = floor.windows.size();
  f.distance = mean(floor.windows), f.lsd_db = mean(floor.lsd);
}

// The AR baseline as a spectrum predictor: its expected spectrum along each section's recorded action.
Scores expected_baseline(const ar::PiecewiseArModel& baseline, const MaterialSignals& signals,
                         const std::vector<std::vector<std::vector<double>>>& recorded, const std::vector<double>& floor) {
  std::vector<ArSection> sections;
  for (std::size_t s = 0; s < signals.test.size(); ++s)
    if (!recorded[s].empty())
      sections.push_back(held_start_section(signals.test[s].speed, signals.test[s].force, section_grid(signals.test[s].accel.size()), recorded[s]));
  ArExpectationOptions closed_form_only;
  closed_form_only.renders = 0;
  const ArExpectation e = expected_ar_spectra(baseline, sections, closed_form_only);
  Scores all;
  for (std::size_t s = 0; s < sections.size(); ++s) all.add(score(e.spectra[s], sections[s].recorded, floor));
  all.seconds = e.closed_form_seconds;
  all.rendered_seconds = double(e.closed_form_windows) * double(dataset::kGridStride) / dataset::kSampleRateHz;  // as the models: each window covers the next hop
  return all;
}

MaterialRun run_material(std::size_t m, const MaterialSignals& signals, const Context& c, bool keep_example) {
  MaterialRun run;
  const ar::PiecewiseArModel baseline = baseline_model(signals, c.options);
  const MaterialReferences ref = material_references(signals);
  std::vector<predict::Predictor> predictors;
  for (const ModelInput& input : c.models) predictors.emplace_back(input.model);
  std::vector<std::vector<std::vector<double>>> recorded;
  for (const SectionSignals& section : signals.test) recorded.push_back(grid_spectra(section.accel, section_grid(section.accel.size())));
  std::size_t row = c.first_row[m], grid_section = c.first_section[m];
  for (std::size_t s = 0; s < signals.test.size(); ++s) {
    const SectionSignals& section = signals.test[s];
    const std::vector<std::size_t> grid = section_grid(section.accel.size());
    if (grid.empty()) continue;
    const auto& truth = recorded[s];
    const std::size_t section_row = row, section_index = grid_section;
    for (std::size_t i = 0; i < c.external.size(); ++i)
      score_external(run, i, c.external[i], section_row, section_index, grid, truth, ref.noise);
    row += grid.size(), ++grid_section;
    const Eigen::MatrixXf actions = grid_actions(section, grid);
    std::vector<double> first_render;
    std::vector<std::vector<double>> first_render_spectra;
    run.baseline.add(rendered_baseline(baseline, section, grid, truth, ref.noise, c, derive_seed(c.options.seed, m, s), first_render,
                                       first_render_spectra));
    run.methods[{Kind::mean_spectrum}].add(score(std::vector<std::vector<double>>(truth.size(), ref.mean), truth, ref.noise));
    std::vector<std::vector<double>> stitched_spectra;
    double stitched_predict_seconds = 0;
    for (std::size_t i = 0; i < c.models.size(); ++i) {
      if (c.models[i].model.variant == predict::Variant::per_material) {
        const int index = c.models[i].model.material_index(signals.id);
        run.methods[{Kind::per_material, i}].add(predict_scores(predictors[i], predictors[i].material_code(index), actions, truth, ref.noise, nullptr));
        continue;
      }
      const Codes& codes = c.codes[i][m];
      run.methods[{Kind::unified_new_actions, i}].add(predict_scores(predictors[i], codes.training, actions, truth, ref.noise, nullptr));
      // With several test presses, each window's distance is the mean over them.
      std::vector<Scores> presses;
      for (std::size_t press = 0; press < codes.test_presses.size(); ++press) {
        const bool stitch = int(i) == c.stitched_model && press == 0;
        presses.push_back(predict_scores(predictors[i], codes.test_presses[press], actions, truth, ref.noise, stitch ? &stitched_spectra : nullptr));
        if (stitch) stitched_predict_seconds = presses.back().seconds;
      }
      Scores& new_presses = run.methods[{Kind::unified_new_presses, i}];
      if (!presses.empty()) new_presses.add(average(presses));
    }
    for (const MethodKey& key : c.stitched_keys) {
      std::vector<double> signal;
      run.methods[key].add(stitched_scores(stitched_spectra, grid, truth, ref.noise, stitched_predict_seconds, key,
                                           derive_seed(c.options.seed, 7, m, s), &signal));
      if (c.stitched_key != key) continue;
      const bool first = run.clip.id.empty();
      extend_clip(run.clip, head(section.accel, grid[0], kClipSamples), signal, head(first_render, grid[0], kClipSamples));
      if (!first) continue;
      // The first test section's middle window: report.html's spectra of every material, Fig. 5's example of some.
      const std::size_t j = grid.size() / 2;
      run.clip.id = signals.id, run.clip.name = signals.name;
      run.clip.recorded_spectrum = truth[j], run.clip.model_spectrum = stitched_spectra[j], run.clip.baseline_spectrum = first_render_spectra[j];
      if (!keep_example) continue;
      run.example = {signals.id, signals.name, truth[j], stitched_spectra[j], first_render_spectra[j],
                     head(section.accel, grid[0]), head(signal, 0), head(first_render, grid[0]), {}, {}};
      for (const ExternalPredictions& p : c.external) {
        run.example.external_spectra.push_back({p.name, p.spectra[section_row + j]});
        if (!p.signals.empty()) run.example.external_signals.push_back({p.name, head(p.signals[section_index], 0)});
      }
    }
  }
  run.methods[{Kind::expected_ar}] = expected_baseline(baseline, signals, recorded, ref.noise);
  score_floor(run, m, signals, ref, recorded, c);
  run.floor.baseline_expected = mean(run.methods[{Kind::expected_ar}].windows);
  return run;
}

void check_model(const ModelInput& input, const split::DatasetSplit& split) {
  const predict::Model& m = input.model;
  if (m.dataset_sha256 != split.dataset_sha256 || m.split_sha256 != split.manifest_sha256)
    throw input_error(input.path, "/@dataset_sha256, /@split_sha256",
                      "the model was trained on another dataset or split than " + split.dataset_path + " and " + split.manifest_path,
                      "Evaluate with the dataset and split it was trained on, or train it again");
  for (const split::MaterialSets& s : split.materials)
    if (m.material_index(s.id) < 0)
      throw input_error(input.path, dataset::model_material_ids_path(), "the model does not know material '" + s.id + "'", "Train it on this dataset");
}

// Only the test presses' peaks are encoded: the training presses' latents are in the model.
std::vector<Codes> unified_codes(const ModelInput& input, const split::DatasetSplit& split) {
  const predict::Predictor p(input.model);
  std::vector<Codes> out;
  for (const split::MaterialSets& m : split.materials) {
    Codes c{p.material_code(input.model.material_index(m.id)), {}};
    for (int press : m.presses[split::kTest])
      c.test_presses.push_back(p.encode_descriptors(predict::press_descriptors(split.dataset_path, m.id, press, true, input.model.descriptor)));
    out.push_back(std::move(c));
  }
  return out;
}

// 2-D PCA of the training latents and the test presses' latents.
std::vector<LatentPoint> latent_map(const std::vector<Codes>& codes, const split::DatasetSplit& split) {
  std::vector<LatentPoint> points;
  std::vector<Eigen::VectorXf> latents;
  for (std::size_t m = 0; m < codes.size(); ++m) {
    const split::MaterialSets& s = split.materials[m];
    latents.push_back(codes[m].training.latent);
    points.push_back({s.id, s.name, "training", 0, 0});
    for (const auto& press : codes[m].test_presses) latents.push_back(press.image_latent), points.push_back({s.id, s.name, "test press", 0, 0});
  }
  if (latents.size() < 2) return points;
  Eigen::MatrixXf x(latents.size(), latents.front().size());
  for (std::size_t i = 0; i < latents.size(); ++i) x.row(Eigen::Index(i)) = latents[i].transpose();
  x.rowwise() -= x.colwise().mean();
  const Eigen::JacobiSVD<Eigen::MatrixXf> svd(x, Eigen::ComputeThinV);
  const Eigen::MatrixXf projected = x * svd.matrixV().leftCols(std::min<Eigen::Index>(2, svd.matrixV().cols()));
  for (std::size_t i = 0; i < points.size(); ++i) {
    points[i].x = projected(Eigen::Index(i), 0);
    points[i].y = projected.cols() > 1 ? projected(Eigen::Index(i), 1) : 0.0;
  }
  return points;
}

MaterialComparison compare(const MaterialSignals& m, const MaterialRun& run, const Scores& model, const Scores& baseline) {
  MaterialComparison c{m.id, m.name, model.windows.size(), mean(model.windows), mean(baseline.windows), {}, {}};
  std::vector<double> difference;
  for (std::size_t j = 0; j < model.windows.size(); ++j) difference.push_back(baseline.windows[j] - model.windows[j]);
  c.difference = quartiles(difference);
  c.test = welch_t_test(model.windows, baseline.windows);
  c.model_lsd_db = mean(model.lsd), c.baseline_lsd_db = mean(baseline.lsd);
  const Scores& floor = run.methods.at({Kind::floor});
  c.floor = mean(floor.windows);
  c.mean_spectrum = mean(run.methods.at({Kind::mean_spectrum}).windows);
  c.below_floor = run.floor.kind == "oracle" && beats_oracle(model.windows, floor.windows);
  return c;
}

struct ExperimentSpec {
  std::string id, title;
  MethodKey key;
  std::string model_label;
  std::optional<MethodKey> baseline_key;  // empty: the AR baseline
};

// How the stitched-signal experiment's title names its reconstruction.
std::string reconstruction_phrase(const MethodKey& key) {
  if (key.reconstruction == render::Reconstruction::online) return "the online method (RTISI-LA)";
  if (key.reconstruction == render::Reconstruction::noise) return "white noise shaped to each frame (no phase reconstruction)";
  return "fast Griffin-Lim, " + std::to_string(key.iterations) + " iterations";
}

std::vector<ExperimentSpec> experiment_specs(const std::vector<ModelInput>& models, const Context& c) {
  std::vector<ExperimentSpec> out;
  std::map<predict::Variant, int> count;
  for (const ModelInput& input : models) ++count[input.model.variant];
  for (std::size_t i = 0; i < models.size(); ++i) {
    const std::string suffix = count[models[i].model.variant] > 1 ? " (" + models[i].label + ")" : "";
    const std::string label = predict::variant_name(models[i].model.variant) + " model " + models[i].label;
    if (models[i].model.variant == predict::Variant::per_material) {
      out.push_back({model_kind_name(Kind::per_material) + suffix, "Per-material models on new actions (test sections of each material)", {Kind::per_material, i}, label, {}});
      continue;
    }
    out.push_back({model_kind_name(Kind::unified_new_actions) + suffix, "Unified model on new actions, with the training presses' texture", {Kind::unified_new_actions, i}, label, {}});
    out.push_back({model_kind_name(Kind::unified_new_presses) + suffix, "Unified model on new actions and a new press (the test press, recognised)", {Kind::unified_new_presses, i}, label, {}});
  }
  // Against the action-blind predictor: does the model use the actions at all?
  for (std::size_t i = 0; i < models.size(); ++i) {
    const bool unified = models[i].model.variant == predict::Variant::unified;
    const std::string suffix = count[models[i].model.variant] > 1 ? " (" + models[i].label + ")" : "";
    const std::string label = predict::variant_name(models[i].model.variant) + " model " + models[i].label;
    const std::vector<std::pair<Kind, std::string>> tested =
        unified ? std::vector<std::pair<Kind, std::string>>{{Kind::unified_new_actions, "Unified model (new actions, training presses)"},
                                                            {Kind::unified_new_presses, "Unified model (new actions, new press)"}}
                : std::vector<std::pair<Kind, std::string>>{{Kind::per_material, "Per-material models (new actions)"}};
    for (const auto& [kind, what] : tested) {
      const std::string id = model_kind_name(kind);
      out.push_back({id + "-vs-mean-spectrum" + suffix, what + " against each material's mean training spectrum, the best action-blind predictor",
                     {kind, i}, label, MethodKey{Kind::mean_spectrum}});
      out.push_back({id + "-vs-expected-ar" + suffix, what + " against the AR baseline's expected spectrum at each window's action: spectrum against spectrum",
                     {kind, i}, label, MethodKey{Kind::expected_ar}});
    }
  }
  for (std::size_t i = 0; i < c.external.size(); ++i) {
    const ExternalPredictions& p = c.external[i];
    const std::string id = "external-" + p.name, label = p.name + " (" + p.path + ")";
    const std::string what = "External model " + p.name + " (its predicted spectra)";
    out.push_back({id, what + " on the test windows: a model trained outside haptex, scored by the paper's protocol", {Kind::external, i}, label, {}});
    out.push_back({id + "-vs-mean-spectrum", what + " against each material's mean training spectrum, the best action-blind predictor",
                   {Kind::external, i}, label, MethodKey{Kind::mean_spectrum}});
    out.push_back({id + "-vs-expected-ar", what + " against the AR baseline's expected spectrum at each window's action: spectrum against spectrum",
                   {Kind::external, i}, label, MethodKey{Kind::expected_ar}});
    if (!p.signals.empty())
      out.push_back({"stitched-" + id, "External model " + p.name + "'s own time signal of each test section, against the AR baseline rendered",
                     {Kind::external_signal, i}, label, {}});
  }
  if (c.stitched_model >= 0 && c.stitched_key) {
    const MethodKey& key = *c.stitched_key;
    out.push_back({"stitched-" + render::reconstruction_name(key.reconstruction),
                   "Stitched time signal: the unified model's spectra on new actions and a new press, turned into vibration by " +
                       reconstruction_phrase(key),
                   key, "unified model " + models[std::size_t(c.stitched_model)].label, {}});
  }
  return out;
}

std::string method_setting(const MethodKey& key, const Context& c) {
  const std::vector<ModelInput>& models = c.models;
  if (key.is_external()) return c.external[key.model].description();
  if (key.kind == Kind::stitched) {
    if (key.reconstruction == render::Reconstruction::fgla) return std::to_string(key.iterations) + " iterations";
    if (key.reconstruction == render::Reconstruction::online) return "look-ahead 3 frames, scattered";
    return "frame by frame, no look-ahead";
  }
  const ModelInput& m = models[key.model];
  return m.label + ", " + std::to_string(m.model.config.value("predictor_hidden", 0)) + " hidden";
}

std::string method_name(const MethodKey& key, const Context& c) {
  if (key.is_external()) return c.external[key.model].name + (key.kind == Kind::external_signal ? " (external, signal)" : " (external)");
  if (key.kind != Kind::stitched) return model_kind_name(key.kind);
  if (key.reconstruction == render::Reconstruction::fgla) return "unified + FGLA";
  if (key.reconstruction == render::Reconstruction::online) return "unified + online (RTISI-LA)";
  return "unified + shaped noise";
}

std::string baseline_label(const std::optional<MethodKey>& key, const std::string& baseline, std::size_t repeats) {
  if (!key) return baseline + " (" + std::to_string(repeats) + " renderings per test section)";
  if (key->kind == Kind::expected_ar) return baseline + " expected spectrum at the recorded action (closed form)";
  return "mean training spectrum per material";
}

MaterialRealism material_realism(const MaterialSignals& m, const Scores& s, const MaterialFloor& floor) {
  std::vector<double> lsd, spread;
  for (const SectionRealism& r : s.realism)
    if (std::isfinite(r.section_lsd_db) && std::isfinite(r.spread_ratio)) lsd.push_back(r.section_lsd_db), spread.push_back(r.spread_ratio);
  if (lsd.empty()) return {m.id, m.name};
  const double distance = mean(s.windows);
  return {m.id, m.name, mean(lsd), mean(spread), distance, floor.kind == "oracle" ? distance / floor.distance : kNotMeasured,
          distance / floor.rendered};
}

// One time-domain method's realism over the materials; no key: the AR baseline as rendered.
Realism realism_of(const std::optional<MethodKey>& key, const std::string& method, const std::string& setting,
                   const std::vector<MaterialSignals>& signals, const std::vector<MaterialRun>& runs) {
  Realism r{method, setting, {}};
  for (std::size_t m = 0; m < runs.size(); ++m) {
    const auto it = key ? runs[m].methods.find(*key) : runs[m].methods.end();
    const Scores* s = !key ? &runs[m].baseline : it == runs[m].methods.end() ? nullptr : &it->second;
    if (s && !s->realism.empty()) r.materials.push_back(material_realism(signals[m], *s, runs[m].floor));
  }
  return r;
}

SpeedPoint point(const std::string& method, const std::string& setting, const Scores& s, const Realism* realism) {
  SpeedPoint p{method, setting, s.seconds / s.rendered_seconds, mean(s.windows)};
  if (!realism) return p;
  const RealismMedians medians = realism_medians(*realism);
  p.kind = "signal", p.section_lsd_db = medians.section_lsd_db, p.spread_ratio = medians.spread_ratio;
  return p;
}

// The predictions files' realism (signals) and speed points (where the file gives its compute time).
void summarise_external(Evaluation& e, const std::vector<MaterialSignals>& signals, const std::vector<MaterialRun>& runs,
                        std::map<MethodKey, Scores>& totals, const Context& c) {
  for (std::size_t i = 0; i < c.external.size(); ++i) {
    const ExternalPredictions& p = c.external[i];
    const MethodKey spectra{Kind::external, i}, signal{Kind::external_signal, i};
    if (std::isfinite(p.query_seconds)) e.speed.push_back(point(method_name(spectra, c), method_setting(spectra, c), totals[spectra], nullptr));
    else e.notes.push_back(p.name + ": " + p.path + " gives no /@query_seconds, so its spectra have no point in the speed chart");
    if (p.signals.empty()) continue;
    e.realism.push_back(realism_of(signal, method_name(signal, c), method_setting(signal, c), signals, runs));
    if (std::isfinite(p.signal_seconds)) e.speed.push_back(point(method_name(signal, c), method_setting(signal, c), totals[signal], &e.realism.back()));
    else e.notes.push_back(p.name + ": " + p.path + " gives no /signals/@seconds, so its signals have no point in the speed chart");
  }
}

// Each clip's material's first test press, its peak image as a small PNG.
void add_press_images(std::vector<MaterialClip>& clips, const split::DatasetSplit& split) {
  const h5::File file = dataset::open_checked(split.dataset_path, dataset::Kind::dataset);
  for (MaterialClip& clip : clips) {
    const auto m = std::find_if(split.materials.begin(), split.materials.end(), [&](const split::MaterialSets& s) { return s.id == clip.id; });
    if (m == split.materials.end() || m->presses[split::kTest].empty()) continue;
    const std::string path = dataset::press_path(clip.id, std::to_string(m->presses[split::kTest].front()));
    cv::Mat peak = dataset::read_press_image(file.root().open_group(path.substr(1)), dataset::layout::kPeak);
    if (peak.cols > kClipImageWidth)
      cv::resize(peak, peak, cv::Size(kClipImageWidth, peak.rows * kClipImageWidth / peak.cols), 0, 0, cv::INTER_AREA);
    clip.press_png = dataset::encode_png(peak);
  }
}

// Floors, realism and the speed-vs-accuracy points over all materials.
void summarise(Evaluation& e, const std::vector<MaterialSignals>& signals, const std::vector<MaterialRun>& runs, const Context& c) {
  Scores base;
  std::map<MethodKey, Scores> totals;
  for (const MaterialRun& r : runs) {
    base.add(r.baseline);
    for (const auto& [key, s] : r.methods) totals[key].add(s);
    if (!r.example.id.empty()) e.examples.push_back(r.example);
    if (!r.clip.id.empty()) e.clips.push_back(r.clip);
    if (!r.baseline.windows.empty()) e.floors.push_back(r.floor);
  }
  const bool any_oracle = std::any_of(e.floors.begin(), e.floors.end(), [](const MaterialFloor& f) { return f.kind == "oracle"; });
  e.floor_kind = any_oracle ? "oracle" : "estimate";
  e.realism.push_back(realism_of(std::nullopt, e.baseline, "rendered along the recorded action", signals, runs));
  e.speed.push_back(point(e.baseline, "order 14-20, 1 rendering", base, &e.realism.back()));
  e.speed.push_back(point(e.baseline + " expected spectrum", "closed form", totals[{Kind::expected_ar}], nullptr));
  for (const MethodKey& key : c.stitched_keys) {
    e.realism.push_back(realism_of(key, method_name(key, c), method_setting(key, c), signals, runs));
    e.speed.push_back(point(method_name(key, c), method_setting(key, c), totals[key], &e.realism.back()));
  }
  const MethodKey oracle_rendered{Kind::oracle_rendered};
  if (totals.count(oracle_rendered))
    e.realism.push_back(realism_of(oracle_rendered, "generating model rendered", "the oracle's model, 10 renderings", signals, runs));
  for (const auto& [key, s] : totals)
    if (key.is_model()) e.speed.push_back(point(method_name(key, c), method_setting(key, c), s, nullptr));
  summarise_external(e, signals, runs, totals, c);
  if (c.truth && !any_oracle)
    e.notes.push_back("--truth " + c.options.truth + " knows none of the materials' recordings: every floor is an estimate");
  if (any_oracle && std::any_of(e.floors.begin(), e.floors.end(), [](const MaterialFloor& f) { return f.kind != "oracle"; }))
    e.notes.push_back("--truth " + c.options.truth + " does not know every material: the others' floor is an estimate");
}

}  // namespace

Evaluation run_evaluation(const split::DatasetSplit& split, const std::vector<ModelInput>& models, const EvaluationOptions& o,
                          const Progress& progress) {
  const auto start = std::chrono::steady_clock::now();
  if (models.empty() && o.predictions.empty())
    throw Error(Error::Kind::bad_input, "evaluate: give at least one model (--model) or predictions file (--predictions NAME=FILE)");
  // Names become file names, which differ only in case on no file system a report may be copied to.
  const auto lower = [](std::string s) {
    for (char& ch : s) ch = char(std::tolower(static_cast<unsigned char>(ch)));
    return s;
  };
  for (std::size_t i = 0; i < o.predictions.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (lower(o.predictions[i].name) == lower(o.predictions[j].name))
        throw Error(Error::Kind::bad_input, "evaluate: two --predictions are named '" + o.predictions[j].name + "' and '" + o.predictions[i].name +
                                                "' (alike but for case): give each its own name");
  for (const ModelInput& input : models) check_model(input, split);
  Evaluation e;
  e.dataset = {split.dataset_path, split.dataset_sha256};
  e.split = {split.manifest_path, split.manifest_sha256};
  for (const ModelInput& input : models) e.models.push_back({input.path, sha256_file(input.path)});
  e.baseline = o.baseline == Baseline::ar_refit ? "ar-refit" : "hatt-published";
  e.reconstruct = o.reconstruct ? render::reconstruction_name(*o.reconstruct) : "none";
  e.repeats = o.repeats;

  std::vector<std::vector<Codes>> codes(models.size());
  int stitched = -1;
  for (std::size_t i = 0; i < models.size(); ++i)
    if (models[i].model.variant == predict::Variant::unified) {
      codes[i] = unified_codes(models[i], split);
      if (stitched < 0) stitched = int(i), e.latents = latent_map(codes[i], split);
    }
  std::optional<dataset::Truth> truth;
  if (!o.truth.empty()) truth = dataset::read_truth_file(o.truth);
  if (truth && truth->sample_rate_hz != dataset::kSampleRateHz)  // the oracle's windows and action points count 10 kHz samples
    throw input_error(o.truth, "/@sample_rate_hz", "is " + std::to_string(truth->sample_rate_hz) + " Hz, not the evaluation's 10 kHz",
                      "Give the truth.h5 written with the recordings of this dataset");
  const std::vector<MaterialSignals> signals = read_section_signals(split);
  if (truth && !truth_knows_any(*truth, signals))
    throw input_error(o.truth, "", "knows none of the test recordings of " + split.dataset_path +
                                       " (by their source SHA-256): it was written by another synth run, so its noise-free spectra are of other recordings",
                      "Give the truth.h5 of the synth run that made this dataset's recordings, or leave --truth out");
  const std::vector<GridSection> sections = grid_sections(signals);
  std::vector<ExternalPredictions> external;
  for (const PredictionsInput& input : o.predictions) {
    external.push_back(read_external_predictions(input, split, sections));
    const ExternalPredictions& p = external.back();
    e.predictions.push_back({p.name, p.path, p.sha256, p.source});
  }
  Context c{models, external, {}, {}, codes, o, truth, {}, {}, stitched};
  // Where each material's windows begin in the grid (evaluate/inputs/evaluation_grid.hpp's order).
  std::size_t row = 0, k = 0;
  for (std::size_t m = 0; m < signals.size(); ++m) {
    c.first_row.push_back(row), c.first_section.push_back(k);
    for (; k < sections.size() && sections[k].material == m; ++k) row += sections[k].windows;
  }
  if (stitched >= 0 && o.reconstruct) {
    for (std::size_t n : o.fgla_iterations) c.stitched_keys.push_back(reconstruction_key(render::Reconstruction::fgla, n));
    c.stitched_keys.push_back(reconstruction_key(render::Reconstruction::online));
    c.stitched_keys.push_back(reconstruction_key(render::Reconstruction::noise));
    // FGLA's experiment runs the most iterations scored.
    c.stitched_key = *o.reconstruct == render::Reconstruction::fgla
                         ? reconstruction_key(*o.reconstruct, *std::max_element(o.fgla_iterations.begin(), o.fgla_iterations.end()))
                         : reconstruction_key(*o.reconstruct);
  }
  if (stitched < 0) e.notes.push_back("no unified model: the new-press and stitched-signal experiments and the latent map are left out");
  if (!o.reconstruct) e.notes.push_back("--reconstruct none: no stitched-signal experiment");

  // Figure 5's four materials, spread over the list.
  std::vector<bool> example(signals.size(), false);
  for (std::size_t k = 0; k < std::min<std::size_t>(4, signals.size()); ++k) example[k * signals.size() / std::min<std::size_t>(4, signals.size())] = true;
  std::vector<MaterialRun> runs(signals.size());
  std::mutex mutex;
  std::size_t done = 0;
  parallel_for(signals.size(), [&](std::size_t m) {
    runs[m] = run_material(m, signals[m], c, example[m] && stitched >= 0);
    std::lock_guard lock(mutex);
    if (progress) progress(++done, signals.size(), signals[m].id);
  }, o.threads);

  for (const ExperimentSpec& spec : experiment_specs(models, c)) {
    Experiment x{spec.id, spec.title, spec.model_label, baseline_label(spec.baseline_key, e.baseline, o.repeats), {}};
    for (std::size_t m = 0; m < signals.size(); ++m) {
      if (runs[m].baseline.windows.empty()) continue;
      const Scores& versus = spec.baseline_key ? runs[m].methods.at(*spec.baseline_key) : runs[m].baseline;
      x.materials.push_back(compare(signals[m], runs[m], runs[m].methods.at(spec.key), versus));
    }
    e.experiments.push_back(std::move(x));
  }
  summarise(e, signals, runs, c);
  add_press_images(e.clips, split);
  e.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return e;
}

}  // namespace haptex::evaluate
