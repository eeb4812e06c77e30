#include "convert/recordings_writer.hpp"

#include "core/error.hpp"
#include "core/naming.hpp"
#include "core/signal/butterworth.hpp"
#include "core/signal/dft321.hpp"
#include "core/signal/sosfilt.hpp"
#include "dataset/description.hpp"
#include "dataset/layout.hpp"

namespace haptex::convert {

namespace layout = dataset::layout;
namespace {

// Samples are stored as float32: 24 bits of mantissa is beyond any accelerometer's or force
// sensor's resolution and halves the files; all computation happens in double before.
std::vector<float> narrow(const std::vector<double>& x) { return std::vector<float>(x.begin(), x.end()); }

std::vector<float> interleave(const std::vector<double>& a, const std::vector<double>& b, const std::vector<double>& c) {
  std::vector<float> rows(3 * a.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    rows[3 * i] = float(a[i]);
    rows[3 * i + 1] = float(b[i]);
    rows[3 * i + 2] = float(c[i]);
  }
  return rows;
}

void write_signal(h5::Group& group, const std::string& name, const std::vector<float>& values, h5::Shape shape,
                  const std::string& units, const std::string& description) {
  dataset::describe(group.write_array<float>(name, values, shape), units, description);
}

void write_lowpassed(h5::Group& group, const std::string& name, const std::vector<double>& raw,
                     const std::string& units, const std::string& what) {
  static const signal::Sos sos = signal::butter_lowpass_hz(kLowpassOrder, kLowpassCutoffHz, kSampleRateHz);
  write_signal(group, name, narrow(signal::sosfiltfilt(sos, raw)), {raw.size()}, units,
               what + ", 4th-order Butterworth low-pass at 20 Hz run forward and backward (zero phase)");
}

}  // namespace

WrittenRecording write_recording(h5::Group root, const Recording& r) {
  WrittenRecording written{material_id(r.material), 0};
  if (written.material_id.empty())
    throw input_error(r.source_path, "material name", "'" + r.material + "' has no letters or digits to make an id from",
                      "Name the material with at least one ASCII letter or digit");
  // Names that differ only in case, spaces, '_' or '-' are one material (as `haptex align` joins them);
  // the first spelling is kept.
  h5::Group materials = root.require_group(layout::kMaterials);
  const bool first = !materials.has_group(written.material_id);
  h5::Group material = materials.require_group(written.material_id);
  if (first) material.set_attr(layout::kName, r.material);
  h5::Group recordings = material.require_group(layout::kRecordings);
  written.index = static_cast<int>(recordings.children().size());
  h5::Group g = recordings.create_group(std::to_string(written.index));

  const std::size_t n = r.samples();
  const auto& ch = r.channels;
  g.set_attr(layout::kSampleRate, r.sample_rate_hz);
  g.set_attr(layout::kSamples, static_cast<std::int64_t>(n));
  g.set_attr(layout::kDuration, double(n) / r.sample_rate_hz);
  g.set_attr(layout::kLowpassFilterAttr, "butterworth");
  g.set_attr(layout::kLowpassOrderAttr, kLowpassOrder);
  g.set_attr(layout::kLowpassCutoffAttr, kLowpassCutoffHz);
  g.set_attr(layout::kLowpassMethodAttr, "sosfiltfilt, odd padding, default pad length (scipy semantics)");
  g.set_attr(layout::kAccelReduction, "DFT321 frame by frame, phase along the axes' principal direction (Landin et al. 2010; "
                                "schemas/hdf5-layout.md)");
  g.set_attr(layout::kAccelReductionWindow, std::int64_t(signal::kDft321Frames.window));
  g.set_attr(layout::kAccelReductionHop, std::int64_t(signal::kDft321Frames.hop));
  g.set_attr(layout::kSourceFile, r.source_path);
  g.set_attr(layout::kSourceSha256, r.source_sha256);
  if (r.texture) g.set_attr(layout::kHattTexture, *r.texture);
  for (const auto& [name, value] : r.source_numbers) g.set_attr(name, value);
  for (const auto& [name, value] : r.source_texts) g.set_attr(name, value);

  const std::string accel_units = r.units.at("accel"), force_units = r.units.at("force");
  write_signal(g, layout::kAccel, narrow(signal::dft321(ch.at("accel_x"), ch.at("accel_y"), ch.at("accel_z"))), {n},
               accel_units, "tool acceleration, three axes reduced to one with DFT321");
  write_signal(g, layout::kAccelXyz, interleave(ch.at("accel_x"), ch.at("accel_y"), ch.at("accel_z")), {n, 3}, accel_units,
               "raw tool acceleration, columns x, y, z");
  write_signal(g, layout::kForceNormal, narrow(ch.at(layout::kForceNormal)), {n}, force_units, "normal force, unfiltered");
  write_signal(g, layout::kSpeed, narrow(ch.at(layout::kSpeed)), {n}, r.units.at("speed"), "tangential speed, unfiltered");
  write_lowpassed(g, layout::kForceNormalLp, ch.at(layout::kForceNormal), force_units, "normal force");
  write_lowpassed(g, layout::kSpeedLp, ch.at(layout::kSpeed), r.units.at("speed"), "tangential speed");
  if (r.has(layout::kForceTangential))
    write_signal(g, layout::kForceTangential, narrow(ch.at(layout::kForceTangential)), {n}, force_units,
                 "tangential (friction) force, unfiltered");
  if (r.has("position_x"))
    write_signal(g, layout::kPosition, interleave(ch.at("position_x"), ch.at("position_y"), ch.at("position_z")), {n, 3},
                 r.units.at("position"), "tool position, columns x, y, z");
  return written;
}

}  // namespace haptex::convert
