#include "evaluate/run_evaluation.hpp"

#include <time.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <mutex>

#include <Eigen/SVD>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "core/random_seeds.hpp"
#include "core/sha256.hpp"
#include "evaluate/ar_refit.hpp"
#include "evaluate/griffin_lim.hpp"
#include "evaluate/hatt_published.hpp"
#include "evaluate/online_reconstruction.hpp"
#include "evaluate/section_signals.hpp"
#include "evaluate/spectral_distance.hpp"
#include "predict/predictor.hpp"
#include "predict/training_data.hpp"

namespace haptex::evaluate {
namespace {

constexpr double kSampleRate = 10000.0;
constexpr std::size_t kExampleSamples = 2000;

// Compute time on this thread: the materials run in parallel, and wall time would count the others.
double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// Per-window distances of one method and what computing it cost.
struct Scores {
  std::vector<double> windows;
  double seconds = 0, rendered_seconds = 0;
  void add(const Scores& o) {
    windows.insert(windows.end(), o.windows.begin(), o.windows.end());
    seconds += o.seconds, rendered_seconds += o.rendered_seconds;
  }
};

struct MaterialRun {
  Scores baseline;
  std::map<std::string, Scores> methods;  // by method key (see method_keys)
  Example example;
};

// The codes one unified model gives a material: its training latent mean and each test press.
struct Codes {
  predict::TextureCode training;
  std::vector<predict::TextureCode> test_presses;
};

std::vector<double> distances(const std::vector<std::vector<double>>& predicted, const std::vector<std::vector<double>>& truth) {
  std::vector<double> out;
  for (std::size_t j = 0; j < truth.size(); ++j) out.push_back(spectrum_distance(predicted[j], truth[j]));
  return out;
}

ar::PiecewiseArModel baseline_model(const MaterialSignals& m, const EvaluationOptions& o) {
  if (o.baseline == Baseline::hatt_published) return load_hatt_published(o.hatt_models, m.name);
  const std::vector<TrainingPiece> pieces = m.pieces();
  return ar::PiecewiseArModel(refit_piecewise_ar(m.name, pieces).models);
}

// The model's spectra for every grid window, one single query at a time as a haptic loop asks.
Scores predict_scores(predict::Predictor& p, const predict::TextureCode& code, const Eigen::MatrixXf& actions,
                      const std::vector<std::vector<double>>& truth, std::vector<std::vector<double>>* spectra) {
  std::vector<std::vector<double>> predicted(truth.size(), std::vector<double>(predict::kSpectrumBins));
  std::vector<float> out(predict::kSpectrumBins);
  Scores s;
  const double start = thread_seconds();
  for (std::size_t j = 0; j < truth.size(); ++j) {
    p.predict(code, std::span<const float>(actions.col(Eigen::Index(j)).data(), predict::kActionValues), out);
    std::copy(out.begin(), out.end(), predicted[j].begin());
  }
  s.seconds = thread_seconds() - start;
  s.rendered_seconds = double(truth.size()) * 100 / kSampleRate;  // each prediction covers the next hop
  s.windows = distances(predicted, truth);
  if (spectra) *spectra = std::move(predicted);
  return s;
}

MagnitudeFrames frames_of(const std::vector<std::vector<double>>& spectra) {
  std::vector<double> flat;
  for (const auto& s : spectra) flat.insert(flat.end(), s.begin(), s.end());
  return target_magnitudes(std::span<const double>(flat));
}

std::vector<double> online_signal(const MagnitudeFrames& frames, std::size_t length) {
  OnlineReconstruction online;
  std::vector<double> out;
  for (std::size_t f = 0; f < frames.frames; ++f) {
    const auto hop = online.push(frames.row(f));
    out.insert(out.end(), hop.begin(), hop.end());
  }
  const auto rest = online.flush();
  out.insert(out.end(), rest.begin(), rest.end());
  out.resize(length, 0.0);
  return out;
}

// The stitched signal of the predicted spectra, scored on the same windows (offset grid[0] = frame 0).
Scores stitched_scores(const std::vector<std::vector<double>>& spectra, const std::vector<std::size_t>& grid,
                       const std::vector<std::vector<double>>& truth, double predict_seconds, const std::string& key,
                       std::uint64_t seed, std::vector<double>* signal) {
  const MagnitudeFrames frames = frames_of(spectra);
  const std::size_t length = covered_samples(frames.frames);
  const double start = thread_seconds();
  std::vector<double> x = key == "online" ? online_signal(frames, length)
                                          : griffin_lim(frames, length, {std::stoul(key.substr(5)), 0.99, InitialPhase::random, seed});
  Scores s;
  s.seconds = thread_seconds() - start + predict_seconds;
  s.rendered_seconds = double(spectra.size()) * 100 / kSampleRate;
  std::vector<std::size_t> local;
  for (std::size_t t : grid) local.push_back(t - grid[0]);
  s.windows = distances(grid_spectra(x, local), truth);
  if (signal) *signal = std::move(x);
  return s;
}

std::vector<double> head(const std::vector<double>& v, std::size_t from) {
  const std::size_t end = std::min(v.size(), from + kExampleSamples);
  return from < end ? std::vector<double>(v.begin() + std::ptrdiff_t(from), v.begin() + std::ptrdiff_t(end)) : std::vector<double>{};
}

struct Context {
  const std::vector<ModelInput>& models;
  const std::vector<std::vector<Codes>>& codes;  // [model][material]; empty for per-material models
  const EvaluationOptions& options;
  std::vector<std::string> stitched_keys;  // every reconstruction scored (speed-vs-accuracy points)
  std::string stitched_key;                // the one the stitched-signal experiment reports
  int stitched_model = -1;                 // the first unified model, whose new-press spectra are stitched
};

// The material's mean spectrum over its training and validation sections: the action-blind
// predictor a model of the actions has to beat.
std::vector<double> mean_training_spectrum(const MaterialSignals& signals) {
  std::vector<double> sum(predict::kSpectrumBins, 0.0);
  std::size_t count = 0;
  for (const SectionSignals& s : signals.training)
    for (const auto& spectrum : grid_spectra(s.accel, section_grid(s.accel.size()))) {
      for (std::size_t k = 0; k < sum.size(); ++k) sum[k] += spectrum[k];
      ++count;
    }
  for (double& v : sum) v /= double(std::max<std::size_t>(1, count));
  return sum;
}

MaterialRun run_material(std::size_t m, const MaterialSignals& signals, const Context& c, bool keep_example) {
  MaterialRun run;
  const ar::PiecewiseArModel baseline = baseline_model(signals, c.options);
  const std::vector<double> mean_spectrum = mean_training_spectrum(signals);
  std::vector<predict::Predictor> predictors;
  for (const ModelInput& input : c.models) predictors.emplace_back(input.model);
  for (std::size_t s = 0; s < signals.test.size(); ++s) {
    const SectionSignals& section = signals.test[s];
    const std::vector<std::size_t> grid = section_grid(section.accel.size());
    if (grid.empty()) continue;
    const auto truth = grid_spectra(section.accel, grid);
    const Eigen::MatrixXf actions = grid_actions(section, grid);
    // The baseline: HaTT-style rendering of the recorded force and speed, `repeats` seeds.
    double start = thread_seconds();
    const auto renders = render_repeats(baseline, section.speed, section.force, c.options.repeats, derive_seed(c.options.seed, m, s));
    Scores base;
    base.seconds = thread_seconds() - start;
    base.rendered_seconds = double(c.options.repeats * section.accel.size()) / kSampleRate;
    base.windows.assign(grid.size(), 0.0);
    std::vector<std::vector<double>> first_render_spectra;
    for (std::size_t r = 0; r < renders.size(); ++r) {
      const auto spectra = grid_spectra(renders[r], grid);
      const auto d = distances(spectra, truth);
      for (std::size_t j = 0; j < d.size(); ++j) base.windows[j] += d[j] / double(renders.size());
      if (r == 0) first_render_spectra = spectra;
    }
    run.baseline.add(base);
    run.methods["mean-spectrum"].add({distances(std::vector<std::vector<double>>(truth.size(), mean_spectrum), truth), 0, 0});
    std::vector<std::vector<double>> stitched_spectra;
    double stitched_predict_seconds = 0;
    for (std::size_t i = 0; i < c.models.size(); ++i) {
      const std::string tag = ":" + std::to_string(i);
      if (c.models[i].model.variant == predict::Variant::per_material) {
        const int index = c.models[i].model.material_index(signals.id);
        run.methods["per-material" + tag].add(predict_scores(predictors[i], predictors[i].material_code(index), actions, truth, nullptr));
        continue;
      }
      const Codes& codes = c.codes[i][m];
      run.methods["unified-new-actions" + tag].add(predict_scores(predictors[i], codes.training, actions, truth, nullptr));
      // With several test presses, each window's distance is the mean over them.
      Scores presses;
      for (std::size_t press = 0; press < codes.test_presses.size(); ++press) {
        const bool stitch = int(i) == c.stitched_model && press == 0;
        const Scores scores = predict_scores(predictors[i], codes.test_presses[press], actions, truth, stitch ? &stitched_spectra : nullptr);
        if (stitch) stitched_predict_seconds = scores.seconds;
        presses.windows.resize(scores.windows.size(), 0.0);
        for (std::size_t j = 0; j < scores.windows.size(); ++j) presses.windows[j] += scores.windows[j] / double(codes.test_presses.size());
        presses.seconds += scores.seconds, presses.rendered_seconds += scores.rendered_seconds;
      }
      run.methods["unified-new-presses" + tag].add(presses);
    }
    for (const std::string& key : c.stitched_keys) {
      std::vector<double> signal;
      run.methods[key].add(stitched_scores(stitched_spectra, grid, truth, stitched_predict_seconds, key,
                                           derive_seed(c.options.seed, 7, m, s), &signal));
      if (keep_example && s == 0 && key == c.stitched_key) {
        const std::size_t j = grid.size() / 2;
        run.example = {signals.id, signals.name, truth[j], stitched_spectra[j], first_render_spectra[j],
                       head(section.accel, grid[0]), head(signal, 0), head(renders[0], grid[0])};
      }
    }
  }
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
      throw input_error(input.path, "/materials/ids", "the model does not know material '" + s.id + "'", "Train it on this dataset");
}

// Only the test presses' peaks are encoded: the training presses' latents are in the model.
std::vector<Codes> unified_codes(const ModelInput& input, const split::DatasetSplit& split) {
  const predict::Predictor p(input.model);
  std::vector<Codes> out;
  for (const split::MaterialSets& m : split.materials) {
    Codes c{p.material_code(input.model.material_index(m.id)), {}};
    for (int press : m.presses[split::kTest])
      for (const auto& d : predict::press_descriptors(split.dataset_path, m.id, press, false, input.model.descriptor))
        c.test_presses.push_back(p.encode_descriptor(d));
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
    for (const auto& press : codes[m].test_presses) latents.push_back(press.latent), points.push_back({s.id, s.name, "test press", 0, 0});
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

MaterialComparison compare(const MaterialSignals& m, const Scores& model, const Scores& baseline) {
  MaterialComparison c{m.id, m.name, model.windows.size(), mean(model.windows), mean(baseline.windows), {}, {}};
  std::vector<double> difference;
  for (std::size_t j = 0; j < model.windows.size(); ++j) difference.push_back(baseline.windows[j] - model.windows[j]);
  c.difference = quartiles(difference);
  c.test = welch_t_test(model.windows, baseline.windows);
  return c;
}

struct ExperimentSpec {
  std::string id, title, key;
  std::string model_label;
  std::string baseline_key;  // empty: the AR baseline
};

std::vector<ExperimentSpec> experiment_specs(const std::vector<ModelInput>& models, const Context& c) {
  std::vector<ExperimentSpec> out;
  std::map<predict::Variant, int> count;
  for (const ModelInput& input : models) ++count[input.model.variant];
  for (std::size_t i = 0; i < models.size(); ++i) {
    const std::string tag = ":" + std::to_string(i);
    const std::string suffix = count[models[i].model.variant] > 1 ? " (" + models[i].label + ")" : "";
    const std::string label = predict::variant_name(models[i].model.variant) + " model " + models[i].label;
    if (models[i].model.variant == predict::Variant::per_material) {
      out.push_back({"per-material" + suffix, "Per-material models on new actions (test sections of each material)", "per-material" + tag, label, ""});
      continue;
    }
    out.push_back({"unified-new-actions" + suffix, "Unified model on new actions, with the training presses' texture", "unified-new-actions" + tag, label, ""});
    out.push_back({"unified-new-presses" + suffix, "Unified model on new actions and a new press (the test press)", "unified-new-presses" + tag, label, ""});
  }
  // Against the action-blind predictor: does the model use the actions at all?
  for (std::size_t i = 0; i < models.size(); ++i) {
    const bool unified = models[i].model.variant == predict::Variant::unified;
    const std::string suffix = count[models[i].model.variant] > 1 ? " (" + models[i].label + ")" : "";
    const std::string label = predict::variant_name(models[i].model.variant) + " model " + models[i].label;
    const std::vector<std::pair<std::string, std::string>> tested =
        unified ? std::vector<std::pair<std::string, std::string>>{{"unified-new-actions", "Unified model (new actions, training presses)"},
                                                                   {"unified-new-presses", "Unified model (new actions, new press)"}}
                : std::vector<std::pair<std::string, std::string>>{{"per-material", "Per-material models (new actions)"}};
    for (const auto& [id, what] : tested)
      out.push_back({id + "-vs-mean-spectrum" + suffix, what + " against each material's mean training spectrum, the best action-blind predictor",
                     id + ":" + std::to_string(i), label, "mean-spectrum"});
  }
  if (c.stitched_model >= 0 && !c.stitched_key.empty()) {
    const std::string& key = c.stitched_key;
    out.push_back({key == "online" ? "stitched-online" : "stitched-fgla",
                   "Stitched time signal: the unified model's spectra on new actions and a new press, turned into vibration by " +
                       (key == "online" ? std::string("the online method (RTISI-LA)") : "fast Griffin-Lim, " + key.substr(5) + " iterations"),
                   key, "unified model " + models[std::size_t(c.stitched_model)].label, ""});
  }
  return out;
}

std::string method_setting(const std::string& key, const std::vector<ModelInput>& models) {
  const auto colon = key.find(':');
  if (key.rfind("fgla:", 0) == 0) return key.substr(5) + " iterations";
  if (key == "online") return "look-ahead 3 frames";
  const ModelInput& m = models[std::stoul(key.substr(colon + 1))];
  return m.label + ", " + std::to_string(m.model.config.value("predictor_hidden", 0)) + " hidden";
}

std::string method_name(const std::string& key) {
  if (key.rfind("fgla:", 0) == 0) return "unified + FGLA";
  if (key == "online") return "unified + online (RTISI-LA)";
  return key.substr(0, key.find(':'));
}

}  // namespace

Evaluation run_evaluation(const split::DatasetSplit& split, const std::vector<ModelInput>& models, const EvaluationOptions& o,
                          const Progress& progress) {
  const auto start = std::chrono::steady_clock::now();
  if (models.empty()) throw Error(Error::Kind::bad_input, "evaluate: give at least one model (--model)");
  for (const ModelInput& input : models) check_model(input, split);
  Evaluation e;
  e.dataset = {split.dataset_path, split.dataset_sha256};
  e.split = {split.manifest_path, split.manifest_sha256};
  for (const ModelInput& input : models) e.models.push_back({input.path, sha256_file(input.path)});
  e.baseline = o.baseline == Baseline::ar_refit ? "ar-refit" : "hatt-published";
  e.reconstruct = o.reconstruct == Reconstruction::fgla ? "fgla" : o.reconstruct == Reconstruction::online ? "online" : "none";
  e.repeats = o.repeats;

  std::vector<std::vector<Codes>> codes(models.size());
  int stitched = -1;
  for (std::size_t i = 0; i < models.size(); ++i)
    if (models[i].model.variant == predict::Variant::unified) {
      codes[i] = unified_codes(models[i], split);
      if (stitched < 0) stitched = int(i), e.latents = latent_map(codes[i], split);
    }
  Context c{models, codes, o, {}, {}, stitched};
  if (stitched >= 0 && o.reconstruct != Reconstruction::none) {
    for (std::size_t n : o.fgla_iterations) c.stitched_keys.push_back("fgla:" + std::to_string(n));
    c.stitched_keys.push_back("online");
    c.stitched_key = o.reconstruct == Reconstruction::online
                         ? "online"
                         : "fgla:" + std::to_string(*std::max_element(o.fgla_iterations.begin(), o.fgla_iterations.end()));
  }
  if (stitched < 0) e.notes.push_back("no unified model: the new-press and stitched-signal experiments and the latent map are left out");
  if (o.reconstruct == Reconstruction::none) e.notes.push_back("--reconstruct none: no stitched-signal experiment");

  const std::vector<MaterialSignals> signals = read_section_signals(split);
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
    const std::string against = spec.baseline_key.empty() ? e.baseline + " (" + std::to_string(o.repeats) + " renderings per test section)"
                                                          : "mean training spectrum per material";
    Experiment x{spec.id, spec.title, spec.model_label, against, {}};
    for (std::size_t m = 0; m < signals.size(); ++m) {
      if (runs[m].baseline.windows.empty()) continue;
      const Scores& versus = spec.baseline_key.empty() ? runs[m].baseline : runs[m].methods.at(spec.baseline_key);
      x.materials.push_back(compare(signals[m], runs[m].methods.at(spec.key), versus));
    }
    e.experiments.push_back(std::move(x));
  }
  Scores base;
  std::map<std::string, Scores> totals;
  for (const MaterialRun& r : runs) {
    base.add(r.baseline);
    for (const auto& [key, s] : r.methods) totals[key].add(s);
    if (!r.example.id.empty()) e.examples.push_back(r.example);
  }
  e.speed.push_back({e.baseline, "order 14-20, 1 rendering", base.seconds / base.rendered_seconds, mean(base.windows)});
  for (const auto& [key, s] : totals)
    if (key != "mean-spectrum") e.speed.push_back({method_name(key), method_setting(key, models), s.seconds / s.rendered_seconds, mean(s.windows)});
  e.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return e;
}

}  // namespace haptex::evaluate
