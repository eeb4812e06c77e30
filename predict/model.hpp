#pragma once
// The action-conditional texture model of Heravi et al. (ICRA 2020), as haptex trains it:
//   texture encoder: GelSight contact image -> fixed descriptor -> learned layers -> latent
//   action encoder:  20 normalised action values (force and speed over 45 ms) -> action code
//   predictor:       [latent, action code] -> 100 non-negative spectrum amplitudes
// The per-material variant has no texture encoder: one action encoder and predictor per material.
#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "dataset/window.hpp"
#include "predict/mlp.hpp"
#include "predict/texture_descriptor.hpp"

namespace haptex::predict {

// The model's input and output sizes are the window contract's (dataset/window.hpp).
using dataset::kActionValues, dataset::kTargetBins;

enum class Variant { unified, per_material };
std::string variant_name(Variant variant);

struct Normalisation {
  Eigen::VectorXf descriptor_mean, descriptor_scale;  // of the training images' descriptors
  Eigen::VectorXf action_mean, action_scale;          // of the training windows' 20 values
  // The training range of force (N) and speed (mm/s): inputs are saturated into it, as HaTT's
  // renderer saturates, so the network never extrapolates; a query outside it is flagged.
  float force_min = 0, force_max = 0, speed_min = 0, speed_max = 0;
  Eigen::VectorXf target_scale;  // per bin: outputs are target_scale .* network outputs
};

// Per row of x (one sample per column): the mean and the spread (RMS about the mean, floored at
// 1e-6) that standardising divides by.
void standardisation(const Eigen::MatrixXf& x, Eigen::VectorXf& mean, Eigen::VectorXf& scale);

// One action encoder and predictor (the unified model has one; per-material, one per material).
struct SpectrumNet {
  Mlp action;     // kActionValues -> action code
  Mlp predictor;  // [latent (unified only), action code] -> kTargetBins, softplus output
};

struct Model {
  Variant variant = Variant::unified;
  TextureDescriptorSpec descriptor;
  Normalisation normalisation;
  Mlp texture;     // normalised descriptor -> latent (unified only)
  Mlp classifier;  // latent -> material logits: stage 1's head; recognises a new press (Predictor::recognised)
  std::vector<std::string> material_ids, material_names;
  Eigen::MatrixXf material_latents;  // latent x materials: mean over each material's training images
  std::vector<SpectrumNet> nets;     // unified: 1; per-material: one per material, in material order
  nlohmann::json config = nlohmann::json::object();   // training options
  nlohmann::json metrics = nlohmann::json::object();  // losses, epochs, accuracies
  std::string dataset_sha256, split_sha256;
  std::string file;  // the file it was read from (empty when made in memory): errors name it

  int latent_size() const { return variant == Variant::unified ? int(texture.outputs()) : 0; }
  // Index of a material by id; -1 when absent.
  int material_index(const std::string& id) const;
};

// For texture encoder outputs (columns), the latents the predictor sees: the training materials' mean
// latents weighted by the classifier's probabilities, material_latents x softmax(classifier(x))
// (docs/predict.md, "A new press"). Unified models only.
Eigen::MatrixXf recognised_latents(const Model& model, const Eigen::MatrixXf& image_latents);

}  // namespace haptex::predict
