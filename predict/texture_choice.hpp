#pragma once
// Which texture a command renders or predicts for, as its command line gives it: a training
// material's id, or a GelSight press image (PNG/JPEG, unified models only) with the sensor's
// no-contact frame (optional: without it, the image blurred stands in; texture_descriptor_self_referenced).
#include <string>
#include <vector>

#include "predict/predictor.hpp"

namespace haptex::predict {

struct TextureChoice {
  std::string material, image, reference;
};

// Throws haptex::Error (bad_input) naming model_path for an unknown material or an image given to a
// per-material model, and the image for an unreadable image or a reference of another size. With an
// image, fills `descriptor` (when given) with its texture descriptor.
TextureCode choose_texture(const Predictor& predictor, const std::string& model_path, const TextureChoice& choice,
                           std::vector<float>* descriptor = nullptr);

}  // namespace haptex::predict
