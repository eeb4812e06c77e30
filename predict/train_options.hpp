#pragma once
// What `haptex train` can be told, and what it reports after every epoch.
#include <algorithm>
#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "predict/model.hpp"

namespace haptex::predict {

struct TrainOptions {
  Variant variant = Variant::unified;
  // Sizes (defaults from the sweep in docs/predict.md).
  int latent = 64, texture_hidden = 128;
  int action_hidden = 32, action_layers = 2;
  int predictor_hidden = 256, predictor_layers = 1;
  // Optimisation. Per-material models see about 1/60 of the windows, so they take smaller batches
  // and more epochs (per_material_* below).
  int batch = 256, max_epochs = 200, patience = 60;
  int per_material_batch = 64, per_material_max_epochs = 150, per_material_patience = 15;
  int texture_batch = 64, texture_max_epochs = 80, texture_patience = 10;
  float learning_rate = 1e-3f;
  // Unified model: every material's windows weigh alike in the loss, whatever its vibration level
  // (material_balance_weights in predict/spectrum_training.hpp); off, loud materials rule it.
  bool balance_materials = true;
  // Bins each training target is averaged over (odd; 1: none; predict/target_smoothing.hpp).
  int target_smoothing = 7;
  std::uint64_t seed = 0;
  unsigned threads = 0;  // 0: every core this process may use

  nlohmann::json to_json() const;
};

struct EpochReport {
  std::string stage;     // "texture" (stage 1), "spectrum" (stage 2) or "spectrum <material id>"
  int epoch = 0, max_epochs = 0;
  // Stage 1: cross-entropy; stage 2: mean Euclidean distance (m/s^2), train_loss to the (smoothed) targets the loss fits.
  double train_loss = 0, val_loss = 0;
  double val_accuracy = -1;             // stage 1 only
  double val_weighted = -1;             // stage 2: val_loss weighted as the loss is (what `best` follows); -1: none
  bool best = false;                    // the best validation loss (stage 2: val_weighted) so far: these weights are kept
  double seconds = 0;                   // since training started
};
using EpochCallback = std::function<void(const EpochReport&)>;

// Stops when the validation loss has not improved for `patience` epochs.
class EarlyStopping {
 public:
  explicit EarlyStopping(int patience) : patience_(patience) {}
  bool improved(double val_loss);  // records the epoch; true when it is the best so far
  bool stop() const { return since_best_ >= patience_; }
  // Halve the learning rate after this many epochs without improvement (a plateau), again after as many more.
  bool plateau() const { return since_best_ > 0 && since_best_ % std::max(1, patience_ / 3) == 0; }
  double best() const { return best_; }
  int best_epoch() const { return best_epoch_; }

 private:
  int patience_, since_best_ = 0, epoch_ = 0, best_epoch_ = 0;
  double best_ = 1e300;
};

}  // namespace haptex::predict
