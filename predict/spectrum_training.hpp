#pragma once
// Stage 2: the action encoder and predictor learn the target spectra (Euclidean loss) with Adam
// on mini-batches, stopping early on the validation windows' loss. The texture encoder is frozen:
// a training window sees the latent of a random augmented image of one of its material's training
// presses (a new draw every epoch); a validation window sees its material's validation press,
// recognised as any new press is (recognised_latents).
#include <Eigen/Core>
#include <string>
#include <vector>

#include "predict/model.hpp"
#include "dataset/window.hpp"
#include "predict/train_options.hpp"

namespace haptex::predict {

struct SpectrumProblem {
  const Eigen::MatrixXf* actions = nullptr;  // normalised, kActionValues x windows
  const Eigen::MatrixXf* targets = nullptr;  // kTargetBins x windows: the windows' own spectra
  Eigen::VectorXf target_scale;              // per bin
  std::vector<std::size_t> train, val;       // columns
  // Unified only: each column's material, and per material the latents (columns) of its training
  // images and of its validation presses.
  const std::vector<int>* material = nullptr;
  const std::vector<Eigen::MatrixXf>* train_latents = nullptr;
  const std::vector<Eigen::MatrixXf>* val_latents = nullptr;
  // Per column, how much its squared error counts (empty: 1 each); see material_balance_weights.
  std::vector<float> weight = {};
  // What the loss fits on the training columns when not `targets` (predict/target_smoothing.hpp);
  // same shape as `targets`.
  const Eigen::MatrixXf* fitted = nullptr;
  int latent_size() const { return train_latents ? int(train_latents->front().rows()) : 0; }
};

struct SpectrumSchedule {  // from TrainOptions (unified or per-material)
  int batch = 0, max_epochs = 0, patience = 0;
  std::string stage = "spectrum";
  unsigned threads = 0;
};

struct SpectrumResult {
  SpectrumNet net;
  int epochs = 0, best_epoch = 0;
  // Mean Euclidean distance (m/s^2) to the windows' own spectra at the best epoch.
  double train_distance = 0, val_distance = 0;
};

SpectrumResult train_spectrum_net(const SpectrumProblem& problem, const TrainOptions& options,
                                  const SpectrumSchedule& schedule, const EpochCallback& progress);

// Mean Euclidean distance between the predicted and target spectra of `columns`, with training
// image latents (training) or the validation presses' latents: as it is (m/s^2), and with each
// column's distance times the square root of its weight (what early stopping watches).
struct Distances {
  double plain = 0, weighted = 0;
};
Distances mean_distance(const SpectrumNet& net, const SpectrumProblem& problem, const std::vector<std::size_t>& columns,
                        bool training, unsigned threads);

// Weights that make every material count alike in the unified model's loss (TrainOptions::balance_materials):
// a window's squared error is divided by its material's mean squared target norm over the training
// windows, since the noise a perfect model is left with grows with the vibration level; scaled so that
// the training columns' weights average 1. material: each column's material (-1: none).
std::vector<float> material_balance_weights(const Eigen::MatrixXf& targets, const std::vector<int>& material,
                                            const std::vector<std::size_t>& train, std::size_t materials);

}  // namespace haptex::predict
