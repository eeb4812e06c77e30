#include "synth/hatt_recordings.hpp"

#include "core/ar/texture_renderer.hpp"
#include "synth/recording_assembly.hpp"
#include "synth/seeds.hpp"
#include "synth/stroke_generator.hpp"

namespace haptex::synth {

convert::Recording render_hatt_recording(const ar::PiecewiseArModel& model, double seconds, std::uint64_t seed) {
  const ar::ModelSet& set = model.set();
  const Strokes strokes = generate_strokes({set.max_speed, set.max_force}, {seconds, set.sample_rate_hz},
                                           derive_seed(seed, 1));
  const std::vector<double> accel = ar::render_texture(model, strokes.speed, strokes.force, derive_seed(seed, 2));
  return assemble_recording({set.material, set.texture, set.mu > 0 ? set.mu : 0.3}, strokes, accel,
                            derive_seed(seed, 3));
}

}  // namespace haptex::synth
