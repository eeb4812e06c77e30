#include "dataset/object_paths.hpp"
#include "predict/model_probe.hpp"

#include "core/error.hpp"
#include "core/text/format.hpp"
#include "predict/predictor.hpp"
#include "predict/spectrum_net.hpp"

namespace haptex::predict {
namespace {

// Constant force and speed over the action's 45 ms, at the corners and the middle of the range.
Eigen::MatrixXf probe_actions(const Normalisation& n) {
  const float forces[] = {n.force_min, n.force_max, n.force_min, n.force_max, (n.force_min + n.force_max) / 2};
  const float speeds[] = {n.speed_min, n.speed_min, n.speed_max, n.speed_max, (n.speed_min + n.speed_max) / 2};
  Eigen::MatrixXf actions(kActionValues, 5);
  for (int c = 0; c < 5; ++c) {
    actions.col(c).head(kActionValues / 2).setConstant(forces[c]);
    actions.col(c).tail(kActionValues / 2).setConstant(speeds[c]);
  }
  return actions;
}

void require_finite_texture(const Model& m, const std::string& path) {
  const Eigen::Index length = m.normalisation.descriptor_mean.size();
  Eigen::MatrixXf x(length, 3);  // standardised: the mean, one spread above, one below
  x.col(0).setZero(), x.col(1).setOnes(), x.col(2).setConstant(-1);
  MlpTrace trace;
  forward(m.texture, x, trace);
  if (!trace.out.back().allFinite()) {
    const std::string layer = first_runaway_layer({{dataset::root_path(dataset::layout::kTextureEncoder), trace}});
    throw non_finite_output(path, layer.empty() ? dataset::root_path(dataset::layout::kTextureEncoder) : layer, "descriptors within one spread of the training mean");
  }
  if (!recognised_latents(m, m.material_latents).allFinite() || !recognised_latents(m, trace.out.back()).allFinite())
    throw non_finite_output(path, dataset::root_path(dataset::layout::kClassifier), "the training materials' latents");
}

}  // namespace

bool runs_away(const Eigen::Ref<const Eigen::MatrixXf>& out) { return !out.allFinite() || out.cwiseAbs().maxCoeff() > kRunaway; }

std::string first_runaway_layer(const std::vector<TracedPart>& parts) {
  for (const TracedPart& part : parts)
    for (std::size_t i = 1; i < part.trace.out.size(); ++i)  // out[0] is the part's input
      if (runs_away(part.trace.out[i])) return dataset::layer_path(part.name, i - 1);
  return "";
}

std::string part_that_overflows(int net, std::size_t action_layers, std::size_t layers,
                                const std::function<bool(std::size_t k)>& ran_away) {
  for (std::size_t k = 0; k < layers; ++k)
    if (ran_away(k))
      return k < action_layers ? dataset::layer_path(dataset::net_part_path(net, dataset::layout::kActionEncoder), k)
                               : dataset::layer_path(dataset::net_part_path(net, dataset::layout::kPredictor), k - action_layers);
  return target_scale_path();
}

std::string part_that_overflows(const SpectrumTrace& trace, int net) {
  // out[0] of each part is its input.
  const std::size_t action_layers = trace.action.out.size() - 1, layers = action_layers + trace.predictor.out.size() - 1;
  return part_that_overflows(net, action_layers, layers, [&](std::size_t k) {
    return runs_away(k < action_layers ? trace.action.out[k + 1] : trace.predictor.out[k - action_layers + 1]);
  });
}

bool absurd_spectra(const Eigen::Ref<const Eigen::MatrixXf>& spectra) {
  return !spectra.allFinite() || (spectra.size() > 0 && spectra.cwiseAbs().maxCoeff() > kMostAmplitude);
}

std::string target_scale_path() { return dataset::root_path(dataset::layout::kNormalisation) + "/" + dataset::layout::kTargetScale; }

Error non_finite_output(const std::string& path, const std::string& part, const std::string& input) {
  return input_error(path.empty() ? "(the model in memory)" : path, part,
                     "gives a non-finite or absurd output (an amplitude past " + text::format("%g", double(kMostAmplitude)) +
                         " m/s^2) for " + input + ": its weights, each finite, run away together",
                     "Train the model again (the training that wrote it diverged, or the file was edited)");
}

void require_finite_outputs(const Model& m, const std::string& path) {
  if (m.variant == Variant::unified) require_finite_texture(m, path);
  Predictor predictor(m);
  const Eigen::MatrixXf actions = probe_actions(m.normalisation);
  for (std::size_t k = 0; k < m.material_ids.size(); ++k) {
    const TextureCode code = predictor.material_code(int(k));
    const std::string input = "material '" + m.material_ids[k] + "' across its training range";
    if (!code.first_layer.allFinite())
      throw non_finite_output(path, dataset::layer_path(dataset::net_part_path(code.net, dataset::layout::kPredictor), 0), input);
    SpectrumTrace trace;
    if (absurd_spectra(predictor.trace_batch(code, normalised_actions(m.normalisation, actions), trace)))
      throw non_finite_output(path, part_that_overflows(trace, code.net), input);
  }
}

}  // namespace haptex::predict
