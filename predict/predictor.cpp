#include "dataset/object_paths.hpp"
#include "predict/predictor.hpp"

#include "core/error.hpp"
#include "predict/dense_kernel.hpp"
#include "predict/model_probe.hpp"
#include "predict/spectrum_net.hpp"

namespace haptex::predict {
namespace {

// One dense layer on a vector into a preallocated output.
void apply(const DenseLayer& l, const Eigen::VectorXf& in, Eigen::VectorXf& out) {
  dense_column(l.weight, in, l.bias, l.activation, out);
}

}  // namespace
Predictor::Predictor(const Model& model) : model_(model), action_(kActionValues) {
  std::size_t widest = 0;
  for (const SpectrumNet& net : model.nets) widest = std::max(widest, net.action.layers.size() + net.predictor.layers.size());
  layer_.resize(widest);
  // Sized for the first net: the nets of a model have the same sizes, which keeps predict() from
  // allocating (a net of other sizes would be resized in dense_column, not overrun).
  const SpectrumNet& net = model.nets.at(0);
  std::size_t k = 0;
  for (const auto* mlp : {&net.action, &net.predictor})
    for (const DenseLayer& l : mlp->layers) layer_[k++].resize(l.weight.rows());
}

TextureCode Predictor::encode(const cv::Mat& peak, const cv::Mat& reference) const {
  if (model_.variant != Variant::unified)
    throw failure("a per-material model has no texture encoder: choose the material instead of an image");
  const std::vector<float> d = texture_descriptor(peak, reference, model_.descriptor);
  return encode_descriptor(d);
}

Eigen::VectorXf Predictor::image_latent(std::span<const float> descriptor) const {
  const Normalisation& n = model_.normalisation;
  if (Eigen::Index(descriptor.size()) != n.descriptor_mean.size())
    throw failure("encode: the descriptor has " + std::to_string(descriptor.size()) + " values, the model expects " +
                  std::to_string(n.descriptor_mean.size()));
  Eigen::MatrixXf x = Eigen::Map<const Eigen::VectorXf>(descriptor.data(), Eigen::Index(descriptor.size()));
  x = (x - n.descriptor_mean).cwiseQuotient(n.descriptor_scale);
  MlpTrace trace;
  forward(model_.texture, x, trace);
  return trace.out.back().col(0);
}

TextureCode Predictor::image_code(const Eigen::VectorXf& image_latent) const {
  if (!image_latent.allFinite()) throw non_finite_output(model_.file, dataset::root_path(dataset::layout::kTextureEncoder), "this press");
  TextureCode code = encode_latent(recognised(image_latent));
  if (!code.latent.allFinite()) throw non_finite_output(model_.file, dataset::root_path(dataset::layout::kClassifier), "this press");
  code.image_latent = image_latent;
  return code;
}

TextureCode Predictor::encode_descriptor(std::span<const float> descriptor) const { return image_code(image_latent(descriptor)); }

TextureCode Predictor::encode_descriptors(const std::vector<std::vector<float>>& descriptors) const {
  if (descriptors.empty()) throw failure("encode: no descriptors");
  Eigen::VectorXf sum = Eigen::VectorXf::Zero(model_.latent_size());
  for (const std::vector<float>& d : descriptors) sum += image_latent(d);  // recognised once, for the mean
  return image_code(sum / float(descriptors.size()));
}

Eigen::VectorXf Predictor::recognised(const Eigen::VectorXf& image_latent) const {
  return recognised_latents(model_, image_latent).col(0);
}

TextureCode Predictor::encode_latent(const Eigen::VectorXf& latent) const {
  const DenseLayer& first = model_.nets.at(0).predictor.layers.front();
  TextureCode code;
  code.latent = latent;
  code.first_layer = first.weight.leftCols(latent.size()) * latent + first.bias;
  return code;
}

TextureCode Predictor::material_code(int material) const {
  if (material < 0 || std::size_t(material) >= model_.material_ids.size())
    throw failure("material_code: no material " + std::to_string(material) + " in the model");
  if (model_.variant == Variant::unified) return encode_latent(model_.material_latents.col(material));
  TextureCode code;
  code.net = material;
  code.first_layer = model_.nets.at(std::size_t(material)).predictor.layers.front().bias;
  return code;
}

bool Predictor::predict(const TextureCode& code, std::span<const float> action, std::span<float> spectrum) {
  const Normalisation& n = model_.normalisation;
  std::copy(action.begin(), action.end(), action_.data());
  const bool saturated = saturate_action(n, std::span<float>(action_.data(), std::size_t(action_.size())));
  action_ = (action_ - n.action_mean).cwiseQuotient(n.action_scale);

  const SpectrumNet& net = model_.nets[std::size_t(code.net)];
  std::size_t k = 0;
  const Eigen::VectorXf* in = &action_;
  for (const DenseLayer& l : net.action.layers) apply(l, *in, layer_[k]), in = &layer_[k++];
  // The texture's share of the predictor's first layer was computed once, in the code.
  const DenseLayer& first = net.predictor.layers.front();
  dense_column(first.weight.rightCols(in->size()), *in, code.first_layer, first.activation, layer_[k]);
  in = &layer_[k++];
  for (std::size_t i = 1; i < net.predictor.layers.size(); ++i) apply(net.predictor.layers[i], *in, layer_[k]), in = &layer_[k++];
  Eigen::Map<Eigen::VectorXf> out(spectrum.data(), Eigen::Index(spectrum.size()));
  out = in->cwiseProduct(n.target_scale);
  if (absurd_spectra(out)) throw non_finite_output(model_.file, part_that_overflows(code.net, k), "this press and action");
  return saturated;
}

// part_that_overflows (model_probe.hpp) for predict()'s first `layers` outputs.
std::string Predictor::part_that_overflows(int net, std::size_t layers) const {
  return predict::part_that_overflows(net, model_.nets[std::size_t(net)].action.layers.size(), layers,
                                      [&](std::size_t k) { return runs_away(layer_[k]); });
}

Eigen::MatrixXf Predictor::predict_batch(const TextureCode& code, const Eigen::MatrixXf& actions, std::size_t* out_of_range) const {
  SpectrumTrace trace;
  Eigen::MatrixXf spectra = trace_batch(code, normalised_actions(model_.normalisation, actions, out_of_range), trace);
  if (absurd_spectra(spectra)) throw non_finite_output(model_.file, predict::part_that_overflows(trace, code.net), "this press and these actions");
  return spectra;
}

Eigen::MatrixXf Predictor::trace_batch(const TextureCode& code, const Eigen::MatrixXf& normalised, SpectrumTrace& trace) const {
  const SpectrumNet& net = model_.nets[std::size_t(code.net)];
  forward(net.action, normalised, trace.action);
  // As predict(): the texture's share of the first layer comes from the code, not from a latent per column.
  Mlp tail = net.predictor;
  DenseLayer& first = tail.layers.front();
  first.weight = Eigen::MatrixXf(first.weight.rightCols(net.action.outputs()));
  first.bias = code.first_layer;
  // The output's softplus, the most of a batch's time in Eigen's exp and log1p, in predict()'s kernel.
  const Activation output = tail.layers.back().activation;
  tail.layers.back().activation = Activation::linear;
  forward(tail, trace.action.out.back(), trace.predictor);
  activate_fast(output, trace.predictor.out.back());
  return model_.normalisation.target_scale.asDiagonal() * trace.predictor.out.back();
}

}  // namespace haptex::predict
