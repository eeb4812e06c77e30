#include "predict/model.hpp"

#include <algorithm>

namespace haptex::predict {

std::string variant_name(Variant variant) { return variant == Variant::unified ? "unified" : "per-material"; }

void standardisation(const Eigen::MatrixXf& x, Eigen::VectorXf& mean, Eigen::VectorXf& scale) {
  mean = x.rowwise().mean();
  scale = ((x.colwise() - mean).cwiseAbs2().rowwise().mean().cwiseSqrt().array() + 1e-6f).matrix();
}

Eigen::MatrixXf recognised_latents(const Model& model, const Eigen::MatrixXf& image_latents) {
  MlpTrace trace;
  forward(model.classifier, image_latents, trace);
  Eigen::MatrixXf p = trace.out.back();
  for (Eigen::Index c = 0; c < p.cols(); ++c) {
    p.col(c) = (p.col(c).array() - p.col(c).maxCoeff()).exp().matrix();  // softmax, the largest logit first
    p.col(c) /= p.col(c).sum();
  }
  return model.material_latents * p;
}

int Model::material_index(const std::string& id) const {
  const auto found = std::find(material_ids.begin(), material_ids.end(), id);
  return found == material_ids.end() ? -1 : int(found - material_ids.begin());
}

}  // namespace haptex::predict
