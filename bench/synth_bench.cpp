// Synthetic data speed on one core: piecewise AR rendering (the HaTT model's per-sample loop,
// re-blending at every new speed and force) and the procedural materials' building blocks.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <numbers>

#include "bench/run_benchmarks.hpp"
#include "convert/hatt_model_reader.hpp"
#include "core/ar/lsf.hpp"
#include "core/ar/texture_renderer.hpp"
#include "synth/height_field.hpp"
#include "synth/material_families.hpp"
#include "synth/probe_vibration.hpp"
#include "synth/stroke_generator.hpp"

namespace {

// An order-18 model set (HaTT's typical order) on the corners of [0, 200] mm/s x [0, 4] N.
haptex::ar::PiecewiseArModel corner_models() {
  haptex::ar::ModelSet set;
  set.material = "bench";
  set.max_speed = 200;
  set.max_force = 4;
  set.num_ar_coeff = 18;
  set.speed_list = {0, 200, 0, 200};
  set.force_list = {0, 0, 4, 4};
  set.triangles = {{0, 1, 3}, {0, 3, 2}};
  for (int m = 0; m < 4; ++m) {
    haptex::ar::ArModel model;
    model.number = m + 1;
    for (int i = 0; i < 18; ++i) model.ar_lsf.push_back(std::numbers::pi * (i + 0.5 + 0.3 * std::sin(m + i)) / 19);
    model.ar_coeff = haptex::ar::lsf_to_poly(model.ar_lsf);
    model.ma_coeff = {1};
    model.variance = (m == 3) ? 0.5 : 0.0;
    model.speed = set.speed_list[std::size_t(m)];
    model.force = set.force_list[std::size_t(m)];
    set.models.push_back(model);
  }
  return haptex::ar::PiecewiseArModel(set);
}

void BM_PiecewiseArRendering(benchmark::State& state) {
  const auto strokes = haptex::synth::generate_strokes({200, 4}, {1.0, 10000}, 1);
  haptex::ar::TextureRenderer renderer(corner_models(), 1);
  for (auto _ : state) benchmark::DoNotOptimize(renderer.render(strokes.speed, strokes.force));
  state.SetItemsProcessed(state.iterations() * std::int64_t(strokes.speed.size()));
}
BENCHMARK(BM_PiecewiseArRendering)->Unit(benchmark::kMillisecond);

// The same on a published HaTT model (Book, order 20), when ../shared/data is there.
void BM_PiecewiseArRenderingHattBook(benchmark::State& state) {
  const char* env = std::getenv("HAPTEX_SHARED_DATA");
  const std::string path = std::string(env ? env : "../shared/data") + "/hatt/models/Models_Book.xml";
  if (!std::filesystem::exists(path)) {
    state.SkipWithError("../shared/data/hatt/models is absent (set HAPTEX_SHARED_DATA)");
    return;
  }
  const auto strokes = haptex::synth::generate_strokes({200, 4}, {1.0, 10000}, 1);
  haptex::ar::TextureRenderer renderer(haptex::convert::load_hatt_model(path), 1);
  for (auto _ : state) benchmark::DoNotOptimize(renderer.render(strokes.speed, strokes.force));
  state.SetItemsProcessed(state.iterations() * std::int64_t(strokes.speed.size()));
}
BENCHMARK(BM_PiecewiseArRenderingHattBook)->Unit(benchmark::kMillisecond);

void BM_HeightField1024(benchmark::State& state) {
  const auto spec = haptex::synth::material_spec(4, 0);
  for (auto _ : state) benchmark::DoNotOptimize(haptex::synth::make_height_field(spec.surface, spec.seed));
}
BENCHMARK(BM_HeightField1024)->Unit(benchmark::kMillisecond);

void BM_ProbeVibration(benchmark::State& state) {
  const auto spec = haptex::synth::material_spec(4, 0);
  const auto tip = haptex::synth::smoothed_for_tip(haptex::synth::make_height_field(spec.surface, spec.seed),
                                                   haptex::synth::kTipRadiusMm);
  const haptex::synth::ProbeVibration probe(tip, spec);
  const auto strokes = haptex::synth::generate_strokes({200, 4}, {1.0, 10000}, 1);
  for (auto _ : state)
    benchmark::DoNotOptimize(probe.along_path(strokes.position_x, strokes.position_y, strokes.force, 10000));
  state.SetItemsProcessed(state.iterations() * std::int64_t(strokes.speed.size()));
}
BENCHMARK(BM_ProbeVibration)->Unit(benchmark::kMillisecond);

}  // namespace

int main(int argc, char** argv) {
  return haptex::bench::run_benchmarks(argc, argv);
}
