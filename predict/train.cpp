#include "predict/train.hpp"

#include <mutex>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "predict/spectrum_net.hpp"
#include "predict/spectrum_training.hpp"
#include "predict/target_smoothing.hpp"
#include "predict/texture_training.hpp"

namespace haptex::predict {
namespace {

std::vector<std::size_t> all_rows(const TrainingData& data, std::size_t set) {
  std::vector<std::size_t> out;
  for (const MaterialData& m : data.materials) out.insert(out.end(), m.rows[set].begin(), m.rows[set].end());
  return out;
}

Eigen::MatrixXf columns(const Eigen::MatrixXf& from, const std::vector<std::size_t>& which) {
  Eigen::MatrixXf out(from.rows(), Eigen::Index(which.size()));
  for (std::size_t i = 0; i < which.size(); ++i) out.col(Eigen::Index(i)) = from.col(Eigen::Index(which[i]));
  return out;
}

Normalisation action_normalisation(const TrainingData& data) {
  const Eigen::MatrixXf train = columns(data.action, all_rows(data, split::kTrain));
  Normalisation n;
  standardisation(train, n.action_mean, n.action_scale);
  const Eigen::Index half = train.rows() / 2;
  n.force_min = train.topRows(half).minCoeff(), n.force_max = train.topRows(half).maxCoeff();
  n.speed_min = train.bottomRows(half).minCoeff(), n.speed_max = train.bottomRows(half).maxCoeff();
  const Eigen::MatrixXf targets = columns(data.target, all_rows(data, split::kTrain));
  n.target_scale = ((targets.cwiseAbs2().rowwise().mean().cwiseSqrt()).array() + 1e-9f).matrix();
  return n;
}

double mean_spectrum_distance(const TrainingData& data, const Eigen::MatrixXf& means, std::size_t set) {
  double sum = 0;
  std::size_t count = 0;
  for (std::size_t m = 0; m < data.materials.size(); ++m)
    for (std::size_t c : data.materials[m].rows[set]) {
      sum += (data.target.col(Eigen::Index(c)) - means.col(Eigen::Index(m))).norm();
      ++count;
    }
  return sum / double(std::max<std::size_t>(1, count));
}

nlohmann::json result_json(const SpectrumResult& r) {
  return {{"epochs", r.epochs}, {"best_epoch", r.best_epoch}, {"train_distance", r.train_distance}, {"val_distance", r.val_distance}};
}

// fitted: what the loss fits on the training columns (smoothed_targets), computed before any training.
void train_unified(const TrainingData& data, const TrainOptions& o, const Eigen::MatrixXf& actions, const Eigen::MatrixXf& fitted,
                   Model& model, const EpochCallback& progress) {
  train_texture_encoder(data, o, model, progress);
  std::vector<int> material(std::size_t(data.action.cols()), -1);
  std::vector<Eigen::MatrixXf> train_latents, val_latents;
  for (std::size_t m = 0; m < data.materials.size(); ++m) {
    for (std::size_t set : {split::kTrain, split::kVal, split::kTest})
      for (std::size_t c : data.materials[m].rows[set]) material[c] = int(m);
    train_latents.push_back(texture_latents(model, data.materials[m].images[split::kTrain]));
    // Validation presses as prediction sees a new press: recognised (the classifier is frozen now).
    val_latents.push_back(recognised_latents(model, texture_latents(model, data.materials[m].images[split::kVal])));
  }
  SpectrumProblem p{&actions, &data.target, model.normalisation.target_scale, all_rows(data, split::kTrain),
                    all_rows(data, split::kVal), &material, &train_latents, &val_latents};
  if (o.balance_materials) p.weight = material_balance_weights(data.target, material, p.train, data.materials.size());
  p.fitted = &fitted;
  const SpectrumResult r = train_spectrum_net(p, o, {o.batch, o.max_epochs, o.patience, "spectrum", o.threads}, progress);
  model.nets = {r.net};
  model.metrics["spectrum"] = result_json(r);
}

void train_per_material(const TrainingData& data, const TrainOptions& o, const Eigen::MatrixXf& actions, const Eigen::MatrixXf& fitted,
                        Model& model, const EpochCallback& progress) {
  std::vector<SpectrumResult> results(data.materials.size());
  std::mutex mutex;
  const EpochCallback serialised = [&](const EpochReport& r) {
    std::lock_guard lock(mutex);
    if (progress) progress(r);
  };
  // One material per core; each trains on one thread, so the result does not depend on the core count.
  parallel_for(data.materials.size(), [&](std::size_t m) {
    const MaterialData& md = data.materials[m];
    SpectrumProblem p{&actions, &data.target, model.normalisation.target_scale, md.rows[split::kTrain], md.rows[split::kVal]};
    p.fitted = &fitted;
    results[m] = train_spectrum_net(p, o, {o.per_material_batch, o.per_material_max_epochs, o.per_material_patience,
                                          "spectrum " + md.id, 1}, serialised);
  }, o.threads);
  nlohmann::json per = nlohmann::json::object();
  for (std::size_t m = 0; m < results.size(); ++m) {
    model.nets.push_back(results[m].net);
    per[data.materials[m].id] = result_json(results[m]);
  }
  model.metrics["spectrum"] = per;
}

}  // namespace

Eigen::MatrixXf mean_training_spectra(const TrainingData& data) {
  Eigen::MatrixXf out(data.target.rows(), Eigen::Index(data.materials.size()));
  for (std::size_t m = 0; m < data.materials.size(); ++m)
    out.col(Eigen::Index(m)) = columns(data.target, data.materials[m].rows[split::kTrain]).rowwise().mean();
  return out;
}

Model train_model(const TrainingData& data, const TrainOptions& o, const EpochCallback& progress) {
  if (data.materials.empty()) throw failure("training needs at least one material");
  Model model;
  model.variant = o.variant;
  model.descriptor = data.descriptor;
  model.dataset_sha256 = data.dataset_sha256;
  model.split_sha256 = data.split_sha256;
  for (const MaterialData& m : data.materials) model.material_ids.push_back(m.id), model.material_names.push_back(m.name);
  model.normalisation = action_normalisation(data);
  const Eigen::MatrixXf actions = normalised_actions(model.normalisation, data.action);
  const Eigen::MatrixXf fitted = smoothed_targets(data.target, all_rows(data, split::kTrain), o.target_smoothing);
  if (o.variant == Variant::unified)
    train_unified(data, o, actions, fitted, model, progress);
  else
    train_per_material(data, o, actions, fitted, model, progress);
  model.config = o.to_json();
  const Eigen::MatrixXf means = mean_training_spectra(data);
  model.metrics["mean_spectrum_baseline"] = {{"train_distance", mean_spectrum_distance(data, means, split::kTrain)},
                                             {"val_distance", mean_spectrum_distance(data, means, split::kVal)}};
  return model;
}

}  // namespace haptex::predict
