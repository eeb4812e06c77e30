// Synthetic recordings read back through the real converter, and behave as textures do.
#include <gtest/gtest.h>

#include <filesystem>

#include "convert/field_map.hpp"
#include "convert/hatt_model_reader.hpp"
#include "convert/hatt_recording_reader.hpp"
#include "core/signal/spectrum.hpp"
#include "synth/hatt_recordings.hpp"
#include "synth/material_families.hpp"
#include "synth/probe_vibration.hpp"
#include "synth/recorded_data_xml.hpp"
#include "synth/recording_assembly.hpp"
#include "synth/truth_spectra.hpp"
#include "tests/support/npy.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::synth {
namespace {

double centroid_hz(const double* spectrum) {
  double weighted = 0, total = 0;
  for (int k = 0; k < 100; ++k) {
    weighted += spectrum[k] * 10.0 * (k + 1);
    total += spectrum[k];
  }
  return weighted / total;
}

TEST(SynthRecordings, XmlReadsBackThroughConvert) {
  test::TempDir dir;
  const Strokes strokes = generate_strokes({100, 2}, {0.5, 10000}, 1);
  std::vector<double> accel(strokes.speed.size());
  for (std::size_t i = 0; i < accel.size(); ++i) accel[i] = std::sin(0.3 * double(i));
  const convert::Recording written = assemble_recording({"Cork & Felt", 12, 0.4}, strokes, accel, 5);
  write_recorded_data_xml(dir.file("cork.xml.gz"), written);
  const convert::Recording read = convert::read_hatt_recording_xml(dir.file("cork.xml.gz"), convert::default_field_map());
  EXPECT_EQ(read.material, "Cork & Felt");
  EXPECT_EQ(read.texture, 12);
  ASSERT_EQ(read.samples(), written.samples());
  EXPECT_EQ(read.channels.size(), 9u);
  for (const auto& [channel, values] : written.channels)
    for (std::size_t i = 0; i < values.size(); i += 101) EXPECT_NEAR(read.channels.at(channel)[i], values[i], 5e-7) << channel;
}

TEST(SynthRecordings, TangentialForceFollowsFrictionAndActionsCarryRipple) {
  const Strokes strokes = generate_strokes({100, 2}, {0.5, 10000}, 2);
  std::vector<double> accel(strokes.speed.size(), 0.0);
  for (std::size_t i = 0; i < accel.size(); ++i) accel[i] = 3 * std::sin(2 * M_PI * 150 * double(i) / 10000);
  const convert::Recording r = assemble_recording({"X", std::nullopt, 0.4}, strokes, accel, 1);
  const auto& fn = r.channels.at("force_normal");
  for (std::size_t i = 0; i < fn.size(); i += 37) EXPECT_NEAR(r.channels.at("force_tangential")[i], 0.4 * fn[i], 1e-12);
  double ripple = 0;
  for (std::size_t i = 0; i < fn.size(); ++i) ripple = std::max(ripple, std::abs(fn[i] - strokes.force[i]));
  EXPECT_GT(ripple, 0.02);  // the 150 Hz vibration reaches the load cell
  EXPECT_LT(ripple, 0.05);
}

TEST(SynthRecordings, MaterialSpectraMoveUpWithSpeed) {
  for (int index : {1, 3, 4}) {  // sandpaper, grooved, woven
    const MaterialSpec spec = material_spec(index, 0);
    const HeightField tip = smoothed_for_tip(make_height_field(spec.surface, spec.seed, 512, 8.0), kTipRadiusMm);
    const ProbeVibration probe(tip, spec);
    const dataset::TruthGrid grid = expected_spectra(probe, {200, 4}, 3, {4, 2, 8});
    EXPECT_GT(centroid_hz(grid.spectrum(3, 1)), 1.3 * centroid_hz(grid.spectrum(0, 1))) << spec.name;
    EXPECT_GT(centroid_hz(grid.spectrum(2, 1)), centroid_hz(grid.spectrum(1, 1))) << spec.name;
  }
}

TEST(SynthRecordings, ResonanceRisesWithForce) {
  const MaterialSpec spec = material_spec(1, 0);
  const HeightField tip = smoothed_for_tip(make_height_field(spec.surface, spec.seed, 256, 4.0), kTipRadiusMm);
  const ProbeVibration probe(tip, spec);
  EXPECT_NEAR(probe.resonance_hz(4.0) / probe.resonance_hz(1.0), std::pow(4.0, 1.0 / 6.0), 1e-12);
  EXPECT_GT(probe.resonance_hz(2.0), probe.resonance_hz(1.0));
}

TEST(SynthRecordings, HattModelsAreCoveredByTheirStrokes) {
  const std::string data = test::shared_data_dir();
  if (data.empty()) GTEST_SKIP() << "../shared/data is absent: the published HaTT models are needed";
  const std::string models = data + "/hatt/models";
  int checked = 0;
  for (const auto& entry : std::filesystem::directory_iterator(models)) {
    const ar::ModelSet set = convert::read_hatt_model(entry.path());
    const StrokeLimits limits{set.max_speed, set.max_force};
    // The strokes of recordings 0 and 1 as `haptex synth hatt` (default seed 0, 10 s) renders them.
    const Strokes a = hatt_strokes(set, 10, hatt_recording_seed(0, set.material, 0));
    const Strokes b = hatt_strokes(set, 10, hatt_recording_seed(0, set.material, 1));
    EXPECT_GE(operating_range_coverage({&a, &b}, limits), 0.9) << entry.path();
    ++checked;
  }
  EXPECT_EQ(checked, 60);
}

TEST(SynthRecordings, HattRecordingRendersTheModelsSpectrum) {
  const std::string data = test::shared_data_dir();
  if (data.empty()) GTEST_SKIP() << "../shared/data is absent: the published HaTT models are needed";
  const ar::PiecewiseArModel model = convert::load_hatt_model(data + "/hatt/models/Models_Book.xml");
  const HattRecording rendered = render_hatt_recording(model, 1.0, 9);
  const convert::Recording& a = rendered.recording;
  EXPECT_EQ(a.channels.at("accel_x"), render_hatt_recording(model, 1.0, 9).recording.channels.at("accel_x"));
  // The strokes it was rendered along are the noise-free action truth.h5 keeps.
  EXPECT_EQ(rendered.strokes.speed, hatt_strokes(model.set(), 1.0, 9).speed);
  EXPECT_EQ(rendered.strokes.force.size(), a.samples());
  EXPECT_EQ(a.material, "Book");
  EXPECT_EQ(a.samples(), 10000u);
  double energy = 0;
  for (double v : a.channels.at("accel_z")) energy += v * v;
  EXPECT_GT(energy / 10000, 1e-3);  // a textured surface, not silence
}

}  // namespace
}  // namespace haptex::synth
