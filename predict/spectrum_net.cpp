#include "predict/spectrum_net.hpp"

#include <cmath>

namespace haptex::predict {

const Eigen::MatrixXf& spectrum_forward(const SpectrumNet& net, const Eigen::MatrixXf& latents, const Eigen::MatrixXf& actions,
                                        SpectrumTrace& trace) {
  forward(net.action, actions, trace.action);
  const Eigen::MatrixXf& code = trace.action.out.back();
  trace.input.resize(latents.rows() + code.rows(), actions.cols());
  trace.input.topRows(latents.rows()) = latents;
  trace.input.bottomRows(code.rows()) = code;
  forward(net.predictor, trace.input, trace.predictor);
  return trace.predictor.out.back();
}

void spectrum_backward(const SpectrumNet& net, const SpectrumTrace& trace, Eigen::MatrixXf d_output, SpectrumGradient& gradient) {
  Eigen::MatrixXf d_input;
  backward(net.predictor, trace.predictor, std::move(d_output), gradient.predictor, &d_input);
  // The latent rows stop here: the texture encoder is frozen after stage 1.
  const Eigen::Index code_rows = net.action.outputs();
  backward(net.action, trace.action, d_input.bottomRows(code_rows), gradient.action);
}

bool saturate_action(const Normalisation& n, std::span<float> action) {
  bool changed = false;
  for (std::size_t i = 0; i < action.size(); ++i) {
    const bool force = i < action.size() / 2;
    const float low = force ? n.force_min : n.speed_min, high = force ? n.force_max : n.speed_max;
    float v = action[i];
    if (!std::isfinite(v)) v = n.action_mean[Eigen::Index(i)];
    v = std::min(std::max(v, low), high);
    changed |= v != action[i];
    action[i] = v;
  }
  return changed;
}

Eigen::MatrixXf normalised_actions(const Normalisation& n, Eigen::MatrixXf raw, std::size_t* out_of_range) {
  std::size_t flagged = 0;
  for (Eigen::Index c = 0; c < raw.cols(); ++c)
    flagged += saturate_action(n, std::span<float>(raw.col(c).data(), std::size_t(raw.rows()))) ? 1 : 0;
  if (out_of_range) *out_of_range = flagged;
  raw.colwise() -= n.action_mean;
  return n.action_scale.cwiseInverse().asDiagonal() * raw;
}

}  // namespace haptex::predict
