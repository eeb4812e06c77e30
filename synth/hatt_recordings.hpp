#pragma once
// `haptex synth hatt`: recordings rendered from the published HaTT piecewise AR models, so the real
// pipeline can run on real surfaces' spectra without the (unpublished) recorded data.
#include <cstdint>

#include "convert/recording.hpp"
#include "core/ar/piecewise_model.hpp"

namespace haptex::synth {

// One recording: free-hand strokes covering the model's (speed, force) range up to its maxima,
// vibration rendered sample by sample from the model at each sample's speed and force.
convert::Recording render_hatt_recording(const ar::PiecewiseArModel& model, double seconds, std::uint64_t seed);

}  // namespace haptex::synth
