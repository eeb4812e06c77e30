// Writes one sample recording (tests/support/sample_recording.hpp) as HaTT XML or CSV; `make demo`
// uses it until `haptex synth` exists.
#include <CLI/CLI.hpp>

#include "tests/support/sample_recording.hpp"

int main(int argc, char** argv) {
  haptex::test::SampleRecordingSpec spec;
  std::string output;
  CLI::App app{"Write a sample vibration recording (HaTT recorded-data XML, or CSV for *.csv)"};
  app.add_option("-o,--output", output, "File to write")->required();
  app.add_option("--material", spec.material, "Material name")->capture_default_str();
  app.add_option("--seconds", spec.seconds, "Duration")->capture_default_str();
  app.add_option("--seed", spec.seed, "Random seed")->capture_default_str();
  app.add_option("--roughness", spec.roughness, "Vibration scale")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  const bool csv = output.size() > 4 && output.substr(output.size() - 4) == ".csv";
  haptex::test::write_text_file(output, csv ? haptex::test::sample_recording_csv(spec)
                                            : haptex::test::sample_recording_xml(spec));
  return 0;
}
