#pragma once
// The action encoder and predictor run on a batch (one sample per column), forward and backward:
// training and batch prediction share it. Outputs are before the per-bin target scale.
#include <Eigen/Core>
#include <span>

#include "predict/model.hpp"

namespace haptex::predict {

struct SpectrumTrace {
  MlpTrace action, predictor;
  Eigen::MatrixXf input;  // [latents; action codes]
};

struct SpectrumGradient {
  MlpGradient action, predictor;
  explicit SpectrumGradient(const SpectrumNet& net) : action(net.action), predictor(net.predictor) {}
  void zero() { action.zero(), predictor.zero(); }
  SpectrumGradient& operator+=(const SpectrumGradient& other) {
    action += other.action;
    predictor += other.predictor;
    return *this;
  }
};

// latents: latent x B (0 x B for the per-material variant); actions: normalised, kActionValues x B.
const Eigen::MatrixXf& spectrum_forward(const SpectrumNet& net, const Eigen::MatrixXf& latents,
                                        const Eigen::MatrixXf& actions, SpectrumTrace& trace);
void spectrum_backward(const SpectrumNet& net, const SpectrumTrace& trace, Eigen::MatrixXf d_output,
                       SpectrumGradient& gradient);

// Saturates the raw action values (10 force, 10 speed) into the training range, in place, and
// replaces non-finite values by the training mean. True when anything had to change.
bool saturate_action(const Normalisation& n, std::span<float> action);
// Saturated and standardised copies of raw actions (kActionValues x B); out_of_range counts the
// columns that were saturated.
Eigen::MatrixXf normalised_actions(const Normalisation& n, Eigen::MatrixXf raw, std::size_t* out_of_range = nullptr);

}  // namespace haptex::predict
