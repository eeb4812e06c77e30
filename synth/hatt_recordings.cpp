#include "synth/hatt_recordings.hpp"

#include "core/ar/texture_renderer.hpp"
#include "core/naming.hpp"
#include "synth/recording_assembly.hpp"
#include "core/random_seeds.hpp"
#include "synth/stroke_generator.hpp"

namespace haptex::synth {

std::uint64_t hatt_recording_seed(std::uint64_t seed, const std::string& material, int k) {
  return derive_seed(seed, name_seed(material_id(material)), std::uint64_t(k));
}

Strokes hatt_strokes(const ar::ModelSet& set, double seconds, std::uint64_t recording_seed) {
  return generate_strokes({set.max_speed, set.max_force}, {seconds, set.sample_rate_hz}, derive_seed(recording_seed, 1));
}

HattRecording render_hatt_recording(const ar::PiecewiseArModel& model, double seconds, std::uint64_t seed) {
  const ar::ModelSet& set = model.set();
  HattRecording out{hatt_strokes(set, seconds, seed), {}};
  const std::vector<double> accel = ar::render_texture(model, out.strokes.speed, out.strokes.force, derive_seed(seed, 2));
  out.recording = assemble_recording({set.material, set.texture, set.mu > 0 ? set.mu : 0.3}, out.strokes, accel,
                                     derive_seed(seed, 3));
  return out;
}

}  // namespace haptex::synth
