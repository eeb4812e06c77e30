#include "predict/train_options.hpp"

namespace haptex::predict {

nlohmann::json TrainOptions::to_json() const {
  return {{"variant", variant_name(variant)},
          {"latent", latent},
          {"texture_hidden", texture_hidden},
          {"action_hidden", action_hidden},
          {"action_layers", action_layers},
          {"predictor_hidden", predictor_hidden},
          {"predictor_layers", predictor_layers},
          {"batch", batch},
          {"max_epochs", max_epochs},
          {"patience", patience},
          {"per_material_batch", per_material_batch},
          {"per_material_max_epochs", per_material_max_epochs},
          {"per_material_patience", per_material_patience},
          {"texture_batch", texture_batch},
          {"texture_max_epochs", texture_max_epochs},
          {"texture_patience", texture_patience},
          {"learning_rate", learning_rate},
          {"balance_materials", balance_materials},
          {"target_smoothing", target_smoothing},
          {"seed", seed}};
}

bool EarlyStopping::improved(double val_loss) {
  ++epoch_;
  if (val_loss < best_) {
    best_ = val_loss;
    best_epoch_ = epoch_;
    since_best_ = 0;
    return true;
  }
  ++since_best_;
  return false;
}

}  // namespace haptex::predict
