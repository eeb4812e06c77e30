#pragma once
// Stage 1 (the paper's): the texture encoder learns, with a classifier head on material identity
// (softmax cross-entropy), to tell materials apart from their augmented training press images.
// It is then frozen; its latents are what the predictor sees of a texture.
#include "predict/model.hpp"
#include "predict/train_options.hpp"
#include "predict/training_data.hpp"

namespace haptex::predict {

// Fills model.texture, model.classifier, model.material_latents, the descriptor normalisation and
// model.metrics["texture"] (accuracies on training images and on the unseen validation presses).
void train_texture_encoder(const TrainingData& data, const TrainOptions& options, Model& model, const EpochCallback& progress);

// The latents of descriptors (one per column of the result) under the model's frozen encoder.
Eigen::MatrixXf texture_latents(const Model& model, const Descriptors& descriptors);

}  // namespace haptex::predict
