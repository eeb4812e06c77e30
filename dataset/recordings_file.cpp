#include "dataset/recordings_file.hpp"

#include <cmath>

#include "core/error.hpp"
#include "core/naming.hpp"
#include "core/text/utf8.hpp"
#include "dataset/description.hpp"
#include "dataset/layout.hpp"
#include "dataset/window.hpp"

namespace haptex::dataset {
namespace {

constexpr const char* kConvertAgain = "Convert the recordings again with haptex convert, then align again";

std::vector<float> read_signal(const h5::Group& recording, const char* name, const char* units) {
  if (!recording.has_dataset(name)) throw input_error(recording.file(), recording.object_path() + "/" + name, "is missing", kConvertAgain);
  const h5::Dataset d = recording.open_dataset(name);
  const std::string found = d.has_attr(layout::kUnits) ? d.attr_string(layout::kUnits) : "";
  if (found != units) throw input_error(d.file(), d.object_path(), "units are '" + found + "', expected '" + units + "'", kConvertAgain);
  if (d.shape().size() != 1) throw input_error(d.file(), d.object_path(), "is not a 1-D signal", kConvertAgain);
  // float32 as the layout says (schemas/hdf5-layout.md): a float64 value beyond its range would be read as inf.
  if (d.dtype() != "float32") throw input_error(d.file(), d.object_path(), "holds " + d.dtype() + ", expected float32", kConvertAgain);
  std::vector<float> values = d.read<float>();
  for (std::size_t i = 0; i < values.size(); ++i)
    if (!std::isfinite(values[i]))
      throw input_error(d.file(), d.object_path() + "[" + std::to_string(i) + "]", "is not a finite number", kConvertAgain);
  return values;
}

void write_signal(h5::Group& group, const char* name, const std::vector<float>& values, h5::Shape shape, const std::string& units,
                  const std::string& description) {
  describe(group.write_array<float>(name, values, shape), units, description);
}

void write_attributes(h5::Group& g, const RecordingToWrite& r) {
  g.set_attr(layout::kSampleRate, r.sample_rate_hz);
  g.set_attr(layout::kSamples, static_cast<std::int64_t>(r.samples()));
  g.set_attr(layout::kDuration, double(r.samples()) / r.sample_rate_hz);
  g.set_attr(layout::kLowpassFilterAttr, r.lowpass.filter);
  g.set_attr(layout::kLowpassOrderAttr, r.lowpass.order);
  g.set_attr(layout::kLowpassCutoffAttr, r.lowpass.cutoff_hz);
  g.set_attr(layout::kLowpassMethodAttr, r.lowpass.method);
  g.set_attr(layout::kAccelReduction, r.accel_reduction.method);
  g.set_attr(layout::kAccelReductionWindow, r.accel_reduction.window);
  g.set_attr(layout::kAccelReductionHop, r.accel_reduction.hop);
  g.set_attr(layout::kSourceFile, r.source_path);
  g.set_attr(layout::kSourceSha256, r.source_sha256);
  if (r.texture) g.set_attr(layout::kHattTexture, *r.texture);
  for (const auto& [name, value] : r.source_numbers) g.set_attr(name, value);
  for (const auto& [name, value] : r.source_texts) g.set_attr(name, value);
}

void write_signals(h5::Group& g, const RecordingToWrite& r) {
  const hsize_t n = r.samples();
  write_signal(g, layout::kAccel, r.accel, {n}, r.accel_units, "tool acceleration, three axes reduced to one with DFT321");
  write_signal(g, layout::kAccelXyz, r.accel_xyz, {n, 3}, r.accel_units, "raw tool acceleration, columns x, y, z");
  write_signal(g, layout::kForceNormal, r.force_normal, {n}, r.force_units, "normal force, unfiltered");
  write_signal(g, layout::kSpeed, r.speed, {n}, r.speed_units, "tangential speed, unfiltered");
  write_signal(g, layout::kForceNormalLp, r.force_normal_lp, {n}, r.force_units, "normal force, " + r.lowpass.description);
  write_signal(g, layout::kSpeedLp, r.speed_lp, {n}, r.speed_units, "tangential speed, " + r.lowpass.description);
  if (!r.force_tangential.empty())
    write_signal(g, layout::kForceTangential, r.force_tangential, {n}, r.force_units, "tangential (friction) force, unfiltered");
  if (!r.position.empty()) write_signal(g, layout::kPosition, r.position, {n, 3}, r.position_units, "tool position, columns x, y, z");
}

}  // namespace

WrittenRecording write_recording(h5::Group root, const RecordingToWrite& r) {
  WrittenRecording written{checked_material_id(r.material, r.source_path, "material name"), 0};
  h5::Group materials = root.require_group(layout::kMaterials);
  const bool first = !materials.has_group(written.material_id);
  h5::Group material = materials.require_group(written.material_id);
  if (first) material.set_attr(layout::kName, r.material);
  // Names that differ in letters yet make one id ("Café 1", "Caf u00e9 1") are two surfaces (review 15, R9).
  if (const std::string earlier = first ? r.material : material.attr_string(layout::kName); !same_material_name(earlier, r.material))
    throw input_error(r.source_path, "material name",
                      "'" + text::printable(r.material) + "' and '" + text::printable(earlier) + "' (an earlier recording's) make one material id, " +
                          written.material_id + ", but differ in letters: two materials would become one",
                      "Name them alike if they are one material, or with different letters or digits if not");
  h5::Group recordings = material.require_group(layout::kRecordings);
  written.index = static_cast<int>(recordings.children().size());
  h5::Group g = recordings.create_group(std::to_string(written.index));
  write_attributes(g, r);
  write_signals(g, r);
  return written;
}

RecordingSignals read_recording_signals(const h5::Group& recording) {
  const double rate = recording.has_attr(layout::kSampleRate) ? recording.attr_double(layout::kSampleRate) : 0.0;
  if (std::abs(rate - kSampleRateHz) > 1e-6)
    throw input_error(recording.file(), recording.object_path(), "sample rate " + std::to_string(rate) + " Hz, not 10000",
                      "Resample to 10 kHz and convert again");
  RecordingSignals s{read_signal(recording, layout::kAccel, "m/s^2"), read_signal(recording, layout::kForceNormalLp, "N"),
                     read_signal(recording, layout::kSpeedLp, "mm/s"),
                     recording.has_attr(layout::kSourceSha256) ? recording.attr_string(layout::kSourceSha256) : std::string()};
  if (s.accel.size() != s.force_lp.size() || s.accel.size() != s.speed_lp.size())
    throw input_error(recording.file(), recording.object_path(),
                      std::string(layout::kAccel) + ", " + layout::kForceNormalLp + " and " + layout::kSpeedLp + " differ in length",
                      kConvertAgain);
  return s;
}

}  // namespace haptex::dataset
