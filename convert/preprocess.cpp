#include "convert/preprocess.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "core/error.hpp"
#include "core/signal/butterworth.hpp"
#include "core/signal/dft321.hpp"
#include "core/signal/sosfilt.hpp"
#include "core/text/format.hpp"

namespace haptex::convert {
namespace {

namespace layout = dataset::layout;

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

// Every input value is within float32 (recording_checks.hpp), but what is derived from them can leave it:
// DFT321 of three axes near 3e38, a low-pass overshooting such a force. Stored, that was inf, and the
// file failed haptex's own qa (review 23, F3).
std::vector<float> narrow_derived(const std::vector<double>& x, const Recording& r, const std::string& what) {
  for (std::size_t i = 0; i < x.size(); ++i)
    if (!(std::abs(x[i]) <= std::numeric_limits<float>::max()))
      throw input_error(r.source_path, what, "reaches " + text::format("%.3g", x[i]) + " at sample " + std::to_string(i) +
                                                 ", beyond the 32-bit floats haptex stores",
                        "No sensor gives such values: check the recording's units and scale");
  return narrow(x);
}

std::vector<float> lowpassed(const std::vector<double>& raw, const Recording& r, const std::string& what) {
  static const signal::Sos sos = signal::butter_lowpass_hz(dataset::kLowpassOrder, dataset::kLowpassCutoffHz, kSampleRateHz);
  return narrow_derived(signal::sosfiltfilt(sos, raw), r, what + " low-passed at 20 Hz");
}

}  // namespace

dataset::RecordingToWrite preprocess(const Recording& r) {
  const auto& ch = r.channels;
  dataset::RecordingToWrite w;
  w.material = r.material;
  w.texture = r.texture;
  w.sample_rate_hz = r.sample_rate_hz;
  w.accel_units = r.units.at("accel");
  w.force_units = r.units.at("force");
  w.speed_units = r.units.at("speed");
  w.source_path = r.source_path;
  w.source_sha256 = r.source_sha256;
  w.source_numbers = r.source_numbers;
  w.source_texts = r.source_texts;
  w.lowpass = {"butterworth", dataset::kLowpassOrder, dataset::kLowpassCutoffHz, "sosfiltfilt, odd padding, default pad length (scipy semantics)",
               "4th-order Butterworth low-pass at 20 Hz run forward and backward (zero phase)"};
  static_assert(dataset::kLowpassOrder == 4 && dataset::kLowpassCutoffHz == 20.0, "the description above states them");
  w.accel_reduction = {"DFT321 frame by frame, phase along the axes' principal direction (Landin et al. 2010; schemas/hdf5-layout.md)",
                       std::int64_t(signal::kDft321Frames.window), std::int64_t(signal::kDft321Frames.hop)};
  w.accel = narrow_derived(signal::dft321(ch.at("accel_x"), ch.at("accel_y"), ch.at("accel_z")), r, "the DFT321 of the three acceleration axes");
  w.accel_xyz = interleave(ch.at("accel_x"), ch.at("accel_y"), ch.at("accel_z"));
  w.force_normal = narrow(ch.at(layout::kForceNormal));
  w.speed = narrow(ch.at(layout::kSpeed));
  w.force_normal_lp = lowpassed(ch.at(layout::kForceNormal), r, "the normal force");
  w.speed_lp = lowpassed(ch.at(layout::kSpeed), r, "the speed");
  if (r.has(layout::kForceTangential)) w.force_tangential = narrow(ch.at(layout::kForceTangential));
  if (r.has("position_x")) {
    w.position = interleave(ch.at("position_x"), ch.at("position_y"), ch.at("position_z"));
    w.position_units = r.units.at("position");
  }
  return w;
}

}  // namespace haptex::convert
