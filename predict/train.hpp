#pragma once
// Training as `haptex train` runs it: normalisation from the training windows, stage 1 (texture
// encoder, unified only), stage 2 (action encoder and predictor; per-material: one per material,
// trained in parallel), and the metrics stored with the model.
#include "predict/model.hpp"
#include "predict/train_options.hpp"
#include "predict/training_data.hpp"

namespace haptex::predict {

// The training log haptex train writes beside the model (docs/predict.md).
inline constexpr const char* kTrainingLogFormat = "training-log/1";

// progress may be called from several threads at once in the per-material variant; calls are serialised.
Model train_model(const TrainingData& data, const TrainOptions& options, const EpochCallback& progress = {});

// Per material: the mean training target (the mean-spectrum baseline the model must beat).
Eigen::MatrixXf mean_training_spectra(const TrainingData& data);

}  // namespace haptex::predict
