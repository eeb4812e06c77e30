#pragma once
// A model whose weights are each finite can still overflow 32-bit floats together (a diverged or
// edited training): its spectra would be inf. read_model runs every part of it once on inputs a
// query can reach and refuses the file if any output is not finite, naming the layer where values
// ran away (or the normalisation that overflowed moderate outputs); Predictor checks each spectrum it
// returns as well, for inputs beyond the probes (a far-off new press).
#include <functional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "predict/mlp.hpp"
#include "predict/model.hpp"
#include "predict/spectrum_net.hpp"

namespace haptex::predict {

// Throws haptex::Error (bad_input) naming `path` and the part (/texture_encoder, /classifier,
// /nets/K/action_encoder, /nets/K/predictor) that gives a non-finite output on: descriptors at the
// training mean and one spread either side of it; each material's code; actions of constant force
// and speed at the four corners and the middle of the training range.
void require_finite_outputs(const Model& model, const std::string& path);

// The error for a non-finite output of `part` of the model read from `path`.
[[nodiscard]] Error non_finite_output(const std::string& path, const std::string& part, const std::string& input);

// Values past kRunaway have run away: the nets see standardised inputs, and a trained net's
// activations stay within tens (at most 21 on inputs three spreads out, in the models the tests
// train), so 1e15 is far beyond any of them yet 23 orders of magnitude short of float32's limit,
// where the overflow they lead to shows.
inline constexpr float kRunaway = 1e15f;

// The most a spectrum's amplitude may be, m/s^2 per bin: 1e5 g, beyond anything a hand-held tool
// carries (HaTT's strongest vibrations are tens of m/s^2), and far below where render's synthesis,
// which sums the bins, overflows float32. A model that predicts more has run away (review 4: finite
// weights giving 1e35 passed predict and made render write NaN).
inline constexpr float kMostAmplitude = 1e6f;
// Spectra (bins x columns) that are not finite or past kMostAmplitude.
bool absurd_spectra(const Eigen::Ref<const Eigen::MatrixXf>& spectra);

// One forward pass through a part of the model (/nets/K/action_encoder, ...), layer by layer.
struct TracedPart {
  std::string name;
  const MlpTrace& trace;
};
// The first layer, in the parts' order, whose output is not finite or runs past kRunaway
// ("/nets/0/action_encoder/layers/1"), so an overflow is blamed on the layer where it started, not
// on the one where it showed; "" when every layer stays within it.
std::string first_runaway_layer(const std::vector<TracedPart>& parts);
// "/normalisation/target_scale".
std::string target_scale_path();
// Whether a layer's output is not finite or runs past kRunaway.
bool runs_away(const Eigen::Ref<const Eigen::MatrixXf>& out);
// Where non-finite spectra of /nets/`net` come from: the first of its `layers` layers, the action
// encoder's `action_layers` and then the predictor's, whose output ran away (`ran_away(k)`), else
// /normalisation/target_scale, which made moderate outputs overflow.
std::string part_that_overflows(int net, std::size_t action_layers, std::size_t layers,
                                const std::function<bool(std::size_t k)>& ran_away);
// The same for a traced pass.
std::string part_that_overflows(const SpectrumTrace& trace, int net);

}  // namespace haptex::predict
