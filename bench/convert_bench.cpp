// XML -> HDF5 conversion of one 10 s HaTT-format recording on one core: parsing alone (plain and
// gzip-compressed), and the
// whole `haptex convert hatt` path (parse, DFT321, low-pass filters, compressed HDF5, fsync, rename).
// `bench_convert --export-xml FILE` writes the recording for bench/elementtree_parse.py, the peer.
#include <benchmark/benchmark.h>

#include <filesystem>

#include "bench/run_benchmarks.hpp"
#include "convert/convert_recordings.hpp"
#include "convert/hatt_recording_reader.hpp"
#include "core/sha256.hpp"
#include "tests/support/sample_recording.hpp"
#include "tests/support/temp_dir.hpp"

namespace {

struct Fixture {
  haptex::test::TempDir dir;
  std::string xml = dir.file("recording.xml"), gz = dir.file("recording.xml.gz");
  std::uintmax_t bytes = 0;
  Fixture() {
    haptex::test::SampleRecordingSpec spec;
    spec.seconds = 10;
    haptex::test::write_text_file(xml, haptex::test::sample_recording_xml(spec));
    haptex::test::write_recording_text(gz, haptex::test::sample_recording_xml(spec));
    bytes = std::filesystem::file_size(xml);
  }
};

Fixture& fixture() {
  static Fixture f;
  return f;
}

constexpr std::int64_t kSamples = 100000;  // per channel; 9 channels

void BM_ParseHattXml_10s(benchmark::State& state) {
  const auto map = haptex::convert::default_field_map();
  const std::string xml = fixture().xml;  // made before timing starts
  for (auto _ : state) benchmark::DoNotOptimize(haptex::convert::read_hatt_recording_xml(xml, map));
  state.SetBytesProcessed(state.iterations() * std::int64_t(fixture().bytes));
  state.SetItemsProcessed(state.iterations() * kSamples);
}
BENCHMARK(BM_ParseHattXml_10s)->Unit(benchmark::kMillisecond);

// The same recording gzip-compressed, as haptex synth writes it: decompression on top of parsing
// (bytes counted as the plain XML's, so the rates compare).
void BM_ParseHattXmlGz_10s(benchmark::State& state) {
  const auto map = haptex::convert::default_field_map();
  const std::string gz = fixture().gz;
  for (auto _ : state) benchmark::DoNotOptimize(haptex::convert::read_hatt_recording_xml(gz, map));
  state.SetBytesProcessed(state.iterations() * std::int64_t(fixture().bytes));
  state.SetItemsProcessed(state.iterations() * kSamples);
}
BENCHMARK(BM_ParseHattXmlGz_10s)->Unit(benchmark::kMillisecond);

void BM_Sha256_10sXml(benchmark::State& state) {
  const std::string xml = fixture().xml;
  for (auto _ : state) benchmark::DoNotOptimize(haptex::sha256_file(xml));
  state.SetBytesProcessed(state.iterations() * std::int64_t(fixture().bytes));
}
BENCHMARK(BM_Sha256_10sXml)->Unit(benchmark::kMillisecond);

void BM_ConvertXmlToHdf5_10s(benchmark::State& state) {
  const std::string out = fixture().dir.file("out.h5");
  haptex::convert::ConvertOptions options;
  options.overwrite = true;
  for (auto _ : state) haptex::convert::convert_recordings({fixture().xml}, out, options);
  state.SetBytesProcessed(state.iterations() * std::int64_t(fixture().bytes));
  state.SetItemsProcessed(state.iterations() * kSamples);
}
// Wall-clock: the output's fsync is part of what a user waits for.
BENCHMARK(BM_ConvertXmlToHdf5_10s)->Unit(benchmark::kMillisecond)->UseRealTime();

// Copies the recording for bench/elementtree_parse.py.
int export_xml(const std::string& path) {
  std::filesystem::copy_file(fixture().xml, path, std::filesystem::copy_options::overwrite_existing);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 3 && std::string(argv[1]) == "--export-xml") return export_xml(argv[2]);
  return haptex::bench::run_benchmarks(argc, argv);
}
