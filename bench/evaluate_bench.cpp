// The evaluator's kernels on one core: spectral distance, Welch's test, and phase reconstruction
// (fast Griffin-Lim at several iteration counts, with the accuracy each reaches as a counter, and
// RTISI-LA per frame). bench/run_bench.sh runs torchaudio's Griffin-Lim on the same signal, which
// `bench_evaluate --export-signal FILE` writes (raw little-endian float64, 10 s at 10 kHz).
#include <benchmark/benchmark.h>

#include <cstring>
#include <fstream>
#include <random>

#include "bench/run_benchmarks.hpp"
#include "evaluate/measures/spectral_distance.hpp"
#include "evaluate/measures/welch_test.hpp"
#include "render/griffin_lim.hpp"
#include "render/online_reconstruction.hpp"
#include "render/spectral_convergence.hpp"
#include "tests/render/texture_signal.hpp"

namespace {

using namespace haptex::evaluate;
using namespace haptex::render;

constexpr std::size_t kTenSeconds = 100000;

const std::vector<double>& texture() {
  static const auto x = haptex::test::texture_signal(kTenSeconds, 7);
  return x;
}

const MagnitudeFrames& texture_magnitudes() {
  static const auto s = stft_magnitudes(texture());
  return s;
}

void BM_SpectralDistance_10s(benchmark::State& state) {
  const auto rendered = haptex::test::texture_signal(kTenSeconds, 8);
  for (auto _ : state) benchmark::DoNotOptimize(spectral_distance(rendered, texture()));
  state.SetItemsProcessed(state.iterations() * kTenSeconds);
}
BENCHMARK(BM_SpectralDistance_10s)->Unit(benchmark::kMillisecond);

void BM_WelchTest_1000_1000(benchmark::State& state) {
  std::mt19937_64 engine(3);
  std::normal_distribution<double> noise;
  std::vector<double> a(1000), b(1000);
  for (double& v : a) v = noise(engine);
  for (double& v : b) v = 0.1 + 2.0 * noise(engine);
  for (auto _ : state) benchmark::DoNotOptimize(welch_t_test(a, b));
}
BENCHMARK(BM_WelchTest_1000_1000)->Unit(benchmark::kMicrosecond);

// Args: iterations, momentum in percent. Counters: the spectral convergence reached (dB) and the
// compute time per second of vibration, the two axes of the evaluator's speed-accuracy chart.
void BM_GriffinLim_10s(benchmark::State& state) {
  GriffinLimOptions options;
  options.iterations = static_cast<std::size_t>(state.range(0));
  options.momentum = static_cast<double>(state.range(1)) / 100.0;
  std::vector<double> x;
  for (auto _ : state) {
    x = griffin_lim(texture_magnitudes(), kTenSeconds, options);
    benchmark::DoNotOptimize(x.data());
  }
  state.counters["sc_db"] = spectral_convergence_db(x, texture_magnitudes());
  state.counters["seconds_per_second"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * 10.0, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_GriffinLim_10s)
    ->ArgNames({"iterations", "momentum_pct"})
    ->ArgsProduct({{0, 8, 32, 100}, {99}})
    ->Args({100, 0})  // plain Griffin-Lim
    ->Unit(benchmark::kMillisecond);

// One whole stream through RTISI-LA, for its accuracy.
double online_sc(const OnlineReconstructionOptions& options) {
  const auto& s = texture_magnitudes();
  OnlineReconstruction online(options);
  std::vector<double> x;
  for (std::size_t m = 0; m < s.frames; ++m) {
    const auto block = online.push(s.row(m));
    x.insert(x.end(), block.begin(), block.end());
  }
  const auto rest = online.flush();
  x.insert(x.end(), rest.begin(), rest.end());
  return spectral_convergence_db(x, s);
}

// Args: look-ahead frames, iterations. Time per pushed frame (100 samples, 10 ms of vibration).
void BM_OnlineReconstruction_PerFrame(benchmark::State& state) {
  OnlineReconstructionOptions options;
  options.look_ahead = static_cast<std::size_t>(state.range(0));
  options.iterations = static_cast<std::size_t>(state.range(1));
  const auto& s = texture_magnitudes();
  OnlineReconstruction online(options);
  std::size_t m = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(online.push(s.row(m)).data());
    m = (m + 1) % s.frames;
  }
  state.counters["sc_db"] = online_sc(options);
  state.counters["latency_ms"] = static_cast<double>(online.latency_samples()) / 10.0;
}
BENCHMARK(BM_OnlineReconstruction_PerFrame)
    ->ArgNames({"look_ahead", "iterations"})
    ->ArgsProduct({{0, 1, 3, 5, 8}, {4}})
    ->Unit(benchmark::kMicrosecond);

int export_signal(const char* path) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(texture().data()), static_cast<std::streamsize>(texture().size() * sizeof(double)));
  return out ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 3 && std::strcmp(argv[1], "--export-signal") == 0) return export_signal(argv[2]);
  return haptex::bench::run_benchmarks(argc, argv);
}
