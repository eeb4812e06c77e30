#include <filesystem>
#include <mutex>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/json/schema.hpp"
#include "core/naming.hpp"
#include "core/parallel.hpp"
#include "synth/material_families.hpp"
#include "synth/gelsight_presses.hpp"
#include "synth/probe_vibration.hpp"
#include "synth/recording_assembly.hpp"
#include "core/random_seeds.hpp"
#include "synth/synth_output.hpp"
#include "synth/synth_runs.hpp"
#include "synth/truth_spectra.hpp"

namespace haptex::synth {
namespace {

const StrokeLimits kLimits{200, 4};  // mm/s and N: a person stroking with a hand-held probe

const char* pattern_name(Pattern p) {
  switch (p) {
    case Pattern::grooves: return "grooves";
    case Pattern::weave: return "weave";
    case Pattern::mesh: return "mesh";
    case Pattern::dots: return "dots";
    case Pattern::none: break;
  }
  return "none";
}

nlohmann::json recipe_json(const MaterialSpec& spec) {
  const SurfaceRecipe& s = spec.surface;
  return {{"name", spec.name}, {"id", material_id(spec.name)}, {"family", s.family}, {"seed", std::to_string(spec.seed)},
          {"surface", {{"rms_um", s.rms_um}, {"correlation_mm", s.correlation_mm}, {"anisotropy", s.anisotropy},
                       {"angle_rad", s.angle_rad}, {"pattern", pattern_name(s.pattern)},
                       {"pattern_period_mm", s.pattern_period_mm}, {"pattern_height_um", s.pattern_height_um},
                       {"pattern_angle_rad", s.pattern_angle_rad}}},
          {"resonance_hz_at_1n", spec.resonance_hz}, {"damping", spec.damping}};
}

void write_manifest(const std::string& out, const SynthMaterialsOptions& o, const std::vector<MaterialSpec>& specs) {
  nlohmann::json doc = {{"generator", "haptex synth materials"}, {"source", o.provenance}, {"seed", o.seed},
                        {"tip_radius_mm", kTipRadiusMm},
                        {"limits", {{"max_speed_mm_s", kLimits.max_speed_mm_s}, {"max_force_n", kLimits.max_force_n}}},
                        {"materials", nlohmann::json::array()}};
  for (const auto& spec : specs) doc["materials"].push_back(recipe_json(spec));
  json::write_file(doc, "synth-materials.schema.json", (std::filesystem::path(out) / "materials.json").string());
}

// One material: surface, presses, recordings; returns its truth (recipe, spectra, the recordings' actions).
dataset::MaterialTruth synthesize_material(const MaterialSpec& spec, const SynthMaterialsOptions& o) {
  const HeightField surface = make_height_field(spec.surface, spec.seed);
  const HeightField tip = smoothed_for_tip(surface, kTipRadiusMm);
  RendererOptions optics;
  optics.width = o.width;
  optics.height = o.height;
  MaterialPressOptions presses;
  presses.presses = o.presses;
  write_material_presses(GelSightRenderer(surface, optics), gelsight_directory(o.out, spec.name), spec.name,
                         derive_seed(spec.seed, 1), o.provenance, presses);
  const ProbeVibration probe(tip, spec);
  dataset::MaterialTruth truth{spec.name, "synth-material", "", recipe_json(spec).dump(), std::nullopt, {}};
  for (int k = 0; k < o.recordings; ++k) {
    Strokes strokes = generate_strokes(kLimits, {o.seconds, kSampleRateHz}, derive_seed(spec.seed, 10, std::uint64_t(k)));
    const std::vector<double> accel = probe.along_path(strokes.position_x, strokes.position_y, strokes.force, kSampleRateHz);
    const convert::Recording recording =
        assemble_recording({spec.name, std::nullopt, 0.3}, strokes, accel, derive_seed(spec.seed, 20, std::uint64_t(k)));
    truth.recordings.push_back(write_recording(recording_path(o.out, spec.name, k), k, recording, std::move(strokes)));
  }
  truth.grid = expected_spectra(probe, kLimits, derive_seed(spec.seed, 30));
  return truth;
}

}  // namespace

SynthSummary synth_materials(const SynthMaterialsOptions& o, const Progress& progress) {
  if (o.count < 1) throw input_error("-n", "", "needs at least one material", "Pass -n 1 or more");
  OutputFolder folder(o.out, o.overwrite);
  SynthMaterialsOptions staged = o;
  staged.out = folder.path();
  const std::vector<MaterialSpec> specs = material_specs(o.count, o.seed);
  dataset::Truth truth{kSampleRateHz, kAccelNoise, std::vector<dataset::MaterialTruth>(specs.size())};
  std::mutex mutex;
  std::size_t done = 0;
  folder.fill([&](const std::string&) {
    parallel_for(specs.size(), [&](std::size_t i) {
      truth.materials[i] = synthesize_material(specs[i], staged);
      std::lock_guard lock(mutex);
      if (progress) progress(++done, specs.size(), specs[i].name);
    });
    dataset::write_truth_file((std::filesystem::path(staged.out) / "truth.h5").string(), truth, o.provenance);
    write_manifest(staged.out, o, specs);
  });
  folder.commit();

  SynthSummary summary;
  for (const auto& spec : specs) summary.materials.push_back(spec.name);
  summary.recordings = specs.size() * std::size_t(o.recordings);
  summary.presses = specs.size() * std::size_t(o.presses);
  return summary;
}

}  // namespace haptex::synth
