#pragma once
// `haptex synth hatt`: recordings rendered from the published HaTT piecewise AR models, so the real
// pipeline can run on real surfaces' spectra without the (unpublished) recorded data.
#include <cstdint>
#include <string>

#include "convert/recording.hpp"
#include "core/ar/piecewise_model.hpp"
#include "synth/stroke_generator.hpp"

namespace haptex::synth {

// The seed of recording k of a material, from the user's seed.
std::uint64_t hatt_recording_seed(std::uint64_t seed, const std::string& material, int k);

// The free-hand strokes of a recording: they cover the model's (speed, force) range up to its maxima.
Strokes hatt_strokes(const ar::ModelSet& set, double seconds, std::uint64_t recording_seed);

struct HattRecording {
  Strokes strokes;               // the noise-free action the vibration was rendered along (truth.h5)
  convert::Recording recording;  // as a rig measures it: sensor noise, ripple on force and speed
};

// One recording: hatt_strokes, with vibration rendered sample by sample from the model at each
// sample's speed and force.
HattRecording render_hatt_recording(const ar::PiecewiseArModel& model, double seconds, std::uint64_t recording_seed);

}  // namespace haptex::synth
