#pragma once
// Inference: encode a texture once, then predict a spectrum per action (per millisecond in a
// haptic loop). predict() does not allocate: every buffer is sized when the Predictor is made.
#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <span>
#include <vector>

#include "predict/model.hpp"
#include "predict/spectrum_net.hpp"
#include "dataset/window.hpp"

namespace haptex::predict {

struct TextureCode {
  int net = 0;                  // which SpectrumNet predicts (per-material: the material)
  Eigen::VectorXf latent;       // unified: the texture latent the predictor sees; per-material: empty
  Eigen::VectorXf image_latent; // from an image: the texture encoder's own output, before recognition
  Eigen::VectorXf first_layer;  // the predictor's first layer applied to the latent, plus its bias
};

class Predictor {
 public:
  // Keeps a reference: the model must outlive the predictor.
  explicit Predictor(const Model& model);

  // Unified model: the code of a GelSight press (peak frame and no-contact reference, RGB as
  // texture_descriptor takes them, one size). Throws haptex::Error for the per-material variant.
  // An image is recognised (docs/predict.md, "A new press"): its latent is the training materials'
  // mean latents weighted by the classifier's probabilities for the image's encoder output.
  TextureCode encode(const cv::Mat& peak, const cv::Mat& reference) const;
  TextureCode encode_descriptor(std::span<const float> descriptor) const;
  // Several views of one press (its frames around the peak, each in the 8 augmentations): their mean
  // encoder output, recognised. Throws haptex::Error for none.
  TextureCode encode_descriptors(const std::vector<std::vector<float>>& descriptors) const;
  // The latent the predictor sees for an encoder output: material_latents x softmax(classifier(x)).
  Eigen::VectorXf recognised(const Eigen::VectorXf& image_latent) const;
  TextureCode encode_latent(const Eigen::VectorXf& latent) const;
  // A training material's code: per-material, its own network; unified, its mean training latent.
  TextureCode material_code(int material) const;

  // action: kActionValues raw values (10 force in N, then 10 speed in mm/s, the last the newest);
  // spectrum: kTargetBins amplitudes (m/s^2). Returns true when the action lay outside the
  // training range and was saturated. Allocation-free.
  bool predict(const TextureCode& code, std::span<const float> action, std::span<float> spectrum);

  // Columns of raw actions -> columns of spectra; counts saturated columns in out_of_range.
  Eigen::MatrixXf predict_batch(const TextureCode& code, const Eigen::MatrixXf& actions,
                                std::size_t* out_of_range = nullptr) const;
  // The same pass on actions already normalised (normalised_actions), every layer kept in `trace` and
  // the spectra left unchecked (model_probe.hpp judges them).
  Eigen::MatrixXf trace_batch(const TextureCode& code, const Eigen::MatrixXf& normalised, SpectrumTrace& trace) const;

  const Model& model() const { return model_; }

 private:
  Eigen::VectorXf image_latent(std::span<const float> descriptor) const;  // the texture encoder's output
  std::string part_that_overflows(int net, std::size_t layers) const;
  TextureCode image_code(const Eigen::VectorXf& image_latent) const;     // recognised, with image_latent kept

  const Model& model_;
  Eigen::VectorXf action_;
  std::vector<Eigen::VectorXf> layer_;  // action encoder outputs, then predictor outputs
};

}  // namespace haptex::predict
