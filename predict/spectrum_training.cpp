#include "predict/spectrum_training.hpp"

#include <chrono>
#include <random>

#include "core/error.hpp"
#include "core/random_seeds.hpp"
#include "predict/adam.hpp"
#include "predict/chunked_batch.hpp"
#include "predict/spectrum_net.hpp"

namespace haptex::predict {
namespace {

// The inputs and targets of some columns. Training columns draw one of their material's training
// image latents from (seed, epoch, column); validation columns take their material's validation presses in turn.
struct Batch {
  Eigen::MatrixXf latents, actions, targets;
  Eigen::VectorXf weights;
};

// `targets`: the spectra to compare with (the problem's targets, or what the loss fits).
Batch gather(const SpectrumProblem& p, const Eigen::MatrixXf& targets, const std::size_t* columns, std::size_t n, bool training,
             std::uint64_t draw_seed) {
  Batch b;
  const int latent = p.latent_size();
  b.latents.resize(latent, Eigen::Index(n));
  b.actions.resize(p.actions->rows(), Eigen::Index(n));
  b.targets.resize(targets.rows(), Eigen::Index(n));
  b.weights.resize(Eigen::Index(n));
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t c = columns[i];
    b.weights[Eigen::Index(i)] = p.weight.empty() ? 1.0f : p.weight[c];
    b.actions.col(Eigen::Index(i)) = p.actions->col(Eigen::Index(c));
    b.targets.col(Eigen::Index(i)) = targets.col(Eigen::Index(c));
    if (!latent) continue;
    const Eigen::MatrixXf& from = (training ? *p.train_latents : *p.val_latents)[std::size_t((*p.material)[c])];
    const std::uint64_t pick = training ? derive_seed(draw_seed, c) % std::uint64_t(from.cols()) : c % std::uint64_t(from.cols());
    b.latents.col(Eigen::Index(i)) = from.col(Eigen::Index(pick));
  }
  return b;
}

// Loss in units of the overall target scale, so that the learning rate does not depend on the
// materials' vibration level: sum over bins of ((s_k o_k - y_k) / sigma)^2.
float loss_unit(const SpectrumProblem& p) { return std::max(1e-12f, p.target_scale.squaredNorm() / float(p.target_scale.size())); }

double batch_gradient(const SpectrumNet& net, const SpectrumProblem& p, const Batch& b, float scale, SpectrumGradient& g) {
  SpectrumTrace trace;
  const Eigen::MatrixXf& out = spectrum_forward(net, b.latents, b.actions, trace);
  const Eigen::MatrixXf error = p.target_scale.asDiagonal() * out - b.targets;
  const float unit = loss_unit(p);
  Eigen::MatrixXf d = p.target_scale.asDiagonal() * error * b.weights.asDiagonal() * (2.0f * scale / unit);
  spectrum_backward(net, trace, std::move(d), g);
  return error.colwise().norm().sum();  // reported in the validation's unit, not the loss's
}

}  // namespace

Distances mean_distance(const SpectrumNet& net, const SpectrumProblem& p, const std::vector<std::size_t>& columns, bool training,
                        unsigned threads) {
  const std::size_t chunks = (columns.size() + kChunkColumns - 1) / kChunkColumns;
  std::vector<Distances> sums(chunks);
  parallel_for(chunks, [&](std::size_t c) {
    const std::size_t begin = c * kChunkColumns, n = std::min(columns.size(), begin + kChunkColumns) - begin;
    const Batch b = gather(p, *p.targets, columns.data() + begin, n, training, 0);
    SpectrumTrace trace;
    const Eigen::MatrixXf predicted = p.target_scale.asDiagonal() * spectrum_forward(net, b.latents, b.actions, trace);
    const Eigen::VectorXf distance = (predicted - b.targets).colwise().norm().transpose();
    sums[c] = {distance.sum(), distance.dot(b.weights.cwiseSqrt())};
  }, threads);
  Distances total;
  for (const Distances& d : sums) total.plain += d.plain, total.weighted += d.weighted;
  const double n = double(std::max<std::size_t>(1, columns.size()));
  return {total.plain / n, total.weighted / n};
}

std::vector<float> material_balance_weights(const Eigen::MatrixXf& targets, const std::vector<int>& material,
                                            const std::vector<std::size_t>& train, std::size_t materials) {
  std::vector<double> power(materials, 0.0), count(materials, 0.0);
  for (std::size_t c : train) {
    const auto m = std::size_t(material[c]);
    power[m] += targets.col(Eigen::Index(c)).squaredNorm(), count[m] += 1;
  }
  // A near-silent material must not take all the weight: its level counts as at least 1e-3 of the mean level.
  double level = 0;
  for (std::size_t m = 0; m < materials; ++m) level += power[m] / double(std::max<std::size_t>(1, train.size()));
  std::vector<double> inverse(materials, 0.0);
  double mean = 0;
  for (std::size_t m = 0; m < materials; ++m) {
    if (count[m] > 0) inverse[m] = 1.0 / std::max(power[m] / count[m], std::max(1e-3 * level, 1e-30));
    mean += inverse[m] * count[m] / double(std::max<std::size_t>(1, train.size()));
  }
  std::vector<float> weight(material.size(), 1.0f);
  for (std::size_t c = 0; c < material.size(); ++c)
    if (material[c] >= 0 && mean > 0) weight[c] = float(inverse[std::size_t(material[c])] / mean);
  return weight;
}

SpectrumResult train_spectrum_net(const SpectrumProblem& p, const TrainOptions& o, const SpectrumSchedule& s,
                                  const EpochCallback& progress) {
  if (s.batch <= 0 || s.max_epochs <= 0 || s.patience <= 0)
    throw failure("train: batch, epochs and patience must be positive (" + std::to_string(s.batch) + ", " + std::to_string(s.max_epochs) +
                  ", " + std::to_string(s.patience) + ")");
  if (p.fitted && (p.fitted->rows() != p.targets->rows() || p.fitted->cols() != p.targets->cols()))
    throw failure("train: the fitted targets are not shaped as the targets");
  std::vector<int> action_sizes{int(p.actions->rows())}, predictor_sizes;
  for (int i = 0; i < o.action_layers; ++i) action_sizes.push_back(o.action_hidden);
  predictor_sizes.push_back(p.latent_size() + action_sizes.back());
  for (int i = 0; i < o.predictor_layers; ++i) predictor_sizes.push_back(o.predictor_hidden);
  predictor_sizes.push_back(int(p.targets->rows()));
  const std::uint64_t seed = derive_seed(o.seed, 3, name_seed(s.stage));
  SpectrumResult result;
  result.net = {make_mlp(action_sizes, Activation::relu, Activation::relu, derive_seed(seed, 1)),
                make_mlp(predictor_sizes, Activation::relu, Activation::softplus, derive_seed(seed, 2))};
  SpectrumNet& net = result.net;
  SpectrumNet best = net;
  Adam adam_action(net.action, {o.learning_rate}), adam_predictor(net.predictor, {o.learning_rate});
  SpectrumGradient total(net);
  std::vector<SpectrumGradient> slots;
  EarlyStopping stopping(s.patience);
  std::vector<std::size_t> order = p.train;
  const Eigen::MatrixXf& fitted = p.fitted ? *p.fitted : *p.targets;
  const auto start = std::chrono::steady_clock::now();
  for (int epoch = 1; epoch <= s.max_epochs && !stopping.stop(); ++epoch) {
    const std::uint64_t epoch_seed = derive_seed(seed, 4, std::uint64_t(epoch));
    std::mt19937_64 rng(epoch_seed);
    std::shuffle(order.begin(), order.end(), rng);
    double train_loss = 0;
    for (std::size_t first = 0; first < order.size(); first += std::size_t(s.batch)) {
      const std::size_t n = std::min(order.size() - first, std::size_t(s.batch));
      train_loss += chunked_gradient<SpectrumGradient>(n, slots, total, s.threads, [&](std::size_t begin, std::size_t end, SpectrumGradient& g) {
        return batch_gradient(net, p, gather(p, fitted, order.data() + first + begin, end - begin, true, epoch_seed), 1.0f / float(n), g);
      });
      adam_action.step(net.action, total.action);
      adam_predictor.step(net.predictor, total.predictor);
    }
    const Distances val = mean_distance(net, p, p.val, false, s.threads);
    EpochReport r{s.stage, epoch, s.max_epochs, train_loss / double(std::max<std::size_t>(1, order.size())), val.plain, -1, val.weighted,
                  stopping.improved(val.weighted), std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()};
    if (r.best) best = net, result.val_distance = val.plain;
    if (stopping.plateau())
      for (Adam* adam : {&adam_action, &adam_predictor}) adam->set_learning_rate(adam->learning_rate() / 2);
    result.epochs = epoch;
    if (progress) progress(r);
  }
  result.net = std::move(best);
  result.best_epoch = stopping.best_epoch();
  if (result.best_epoch == 0) result.val_distance = stopping.best();  // no epoch improved (a NaN loss)
  result.train_distance = mean_distance(result.net, p, p.train, true, s.threads).plain;
  return result;
}

}  // namespace haptex::predict
