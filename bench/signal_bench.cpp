// Signal kernels on one core. bench/run_bench.sh compares sosfiltfilt with scipy's in the same run.
#include <benchmark/benchmark.h>

#include <random>

#include "bench/run_benchmarks.hpp"
#include "core/signal/butterworth.hpp"
#include "core/signal/dft321.hpp"
#include "core/signal/resample.hpp"
#include "core/signal/sosfilt.hpp"
#include "core/signal/spectrum.hpp"

namespace {

std::vector<double> noisy_force(std::size_t n) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0, 0.05);
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = 2.0 + 0.5 * std::sin(double(i) * 1e-3) + noise(rng);
  return x;
}

void BM_Sosfiltfilt_1e5(benchmark::State& state) {
  const auto sos = haptex::signal::butter_lowpass(4, 0.004);
  const auto x = noisy_force(100000);
  for (auto _ : state) benchmark::DoNotOptimize(haptex::signal::sosfiltfilt(sos, x));
  state.SetItemsProcessed(state.iterations() * 100000);
}
BENCHMARK(BM_Sosfiltfilt_1e5)->Unit(benchmark::kMicrosecond);

void BM_Dft321_10s(benchmark::State& state) {
  const auto x = noisy_force(100000), y = noisy_force(100000), z = noisy_force(100000);
  for (auto _ : state) benchmark::DoNotOptimize(haptex::signal::dft321(x, y, z));
  state.SetItemsProcessed(state.iterations() * 100000);
}
BENCHMARK(BM_Dft321_10s)->Unit(benchmark::kMicrosecond);

void BM_AmplitudeSpectrum_1000(benchmark::State& state) {
  const auto x = noisy_force(1000);
  std::vector<double> out(100);
  for (auto _ : state) {
    haptex::signal::amplitude_spectrum(x, out);
    benchmark::DoNotOptimize(out.data());
  }
}
BENCHMARK(BM_AmplitudeSpectrum_1000);

// A 60 ms source at 999983 Hz (a prime rate under convert's 1 MHz limit) to 10 kHz: the filter has
// 20 million taps (review 9, F8). bench/scipy_resample_poly.py times scipy on the same input.
void BM_ResamplePoly_999983Hz(benchmark::State& state) {
  std::vector<double> x(60000);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = 0.3 * std::sin(2 * M_PI * 180 * double(i) / 999983.0);
  for (auto _ : state) benchmark::DoNotOptimize(haptex::signal::resample_poly(x, 10000, 999983));
}
BENCHMARK(BM_ResamplePoly_999983Hz)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace

int main(int argc, char** argv) {
  return haptex::bench::run_benchmarks(argc, argv);
}
