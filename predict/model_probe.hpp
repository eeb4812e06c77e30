#pragma once
// A model whose weights are each finite can still overflow 32-bit floats together (a diverged or
// edited training): its spectra would be inf. read_model runs every part of it once on inputs a
// query can reach and refuses the file if any output is not finite, naming the part; Predictor
// checks each spectrum it returns as well, for inputs beyond the probes (a far-off new press).
#include <string>

#include "core/error.hpp"
#include "predict/model.hpp"

namespace haptex::predict {

// Throws haptex::Error (bad_input) naming `path` and the part (/texture_encoder, /classifier,
// /nets/K/action_encoder, /nets/K/predictor) that gives a non-finite output on: descriptors at the
// training mean and one spread either side of it; each material's code; actions of constant force
// and speed at the four corners and the middle of the training range.
void require_finite_outputs(const Model& model, const std::string& path);

// The error for a non-finite output of `part` of the model read from `path`.
[[nodiscard]] Error non_finite_output(const std::string& path, const std::string& part, const std::string& input);

}  // namespace haptex::predict
